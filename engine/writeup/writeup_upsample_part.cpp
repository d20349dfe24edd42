// Part 6 of the write-up: the cube after each level of the student's upsample (its asymmetry), the cube with its face
// diagonals split first (symmetric again), the cube with every edge split first (sharper corners), and the teapot
// after one level, with the numbers that show each effect: how far the corners are from the centre, the degrees.
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "core/value_format.h"
#include "grade/submission.h"
#include "writeup/internal/writeup_parts.h"

namespace meshedit {
namespace {

constexpr int kTeapotResolution = 4;

std::shared_ptr<HalfedgeMesh> cube_mesh() { return std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube())); }

// The cube with the reference's split of each edge `chosen` picks (by the ends' positions), before any upsample.
std::shared_ptr<HalfedgeMesh> cube_split(bool diagonals_only) {
  std::shared_ptr<HalfedgeMesh> cube = cube_mesh();
  std::vector<EdgeId> edges;
  for (const EdgeId e : cube->edges()) {
    const HalfedgeId h = cube->halfedge(e);
    const glm::dvec3 d = cube->position(cube->vertex(h)) - cube->position(cube->vertex(cube->twin(h)));
    const int axes = (d.x != 0.0) + (d.y != 0.0) + (d.z != 0.0);
    if (!diagonals_only || axes == 2) edges.push_back(e);
  }
  for (const EdgeId e : edges) split(*cube, e);
  return cube;
}

// "the 8 corners are 0.577 to 0.612 from the centre; degrees 3 to 6": for each corner of the cube, the vertex of the
// mesh nearest it, and its distance from the centre (one distance when the result is symmetric).
std::string cube_numbers(const HalfedgeMesh& mesh) {
  if (!validate(mesh).ok()) return "";
  double nearest_min = std::numeric_limits<double>::infinity(), nearest_max = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner(((i & 1) != 0) - 0.5, ((i >> 1 & 1) != 0) - 0.5, ((i >> 2 & 1) != 0) - 0.5);
    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 found(0.0);
    for (const VertexId v : mesh.vertices()) {
      const double d = glm::distance(mesh.position(v), corner);
      if (d < best) {
        best = d;
        found = mesh.position(v);
      }
    }
    nearest_min = std::min(nearest_min, glm::length(found));
    nearest_max = std::max(nearest_max, glm::length(found));
  }
  uint32_t low = std::numeric_limits<uint32_t>::max(), high = 0;
  for (const VertexId v : mesh.vertices()) {
    low = std::min(low, mesh.degree(v));
    high = std::max(high, mesh.degree(v));
  }
  const std::string low_distance = format_number(std::round(nearest_min * 1000) / 1000);
  const std::string high_distance = format_number(std::round(nearest_max * 1000) / 1000);
  const std::string corners = low_distance == high_distance
                                  ? "all " + low_distance + " from the centre (symmetric)"
                                  : low_distance + " to " + high_distance + " from the centre";
  return "the 8 corners are " + corners + "; the cube's are 0.866; vertex degrees " + std::to_string(low) + " to " +
         std::to_string(high);
}

MeshPicture level_picture(std::shared_ptr<const HalfedgeMesh> mesh) {
  MeshPicture picture;
  picture.mesh = std::move(mesh);
  return picture;
}

// `levels` of the student's upsample from `start`, one picture each (level 0 first); stops at the first that differs.
WriteupFigure upsampled(const PartCode& code, std::shared_ptr<const HalfedgeMesh> start, int levels,
                        WriteupFigure figure, bool numbers) {
  figure.made_by = code.made_by;
  figure.problem = code.problem;
  figure.pictures.push_back({"level 0", level_picture(start), ""});
  if (numbers) figure.numbers.push_back("level 0: " + cube_numbers(*start));
  std::shared_ptr<const HalfedgeMesh> mesh = std::move(start);
  for (int level = 1; code.code && level <= levels; ++level) {
    ExerciseReport report;
    try {
      report = check_exercise(*code.code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh));
    } catch (const std::exception& e) {  // check_exercise promises not to throw; a bug must not stop the write-up
      report.mine.error = e.what();
    }
    if (report.mine.mesh) {
      mesh = report.mine.mesh;
      figure.pictures.push_back({"level " + std::to_string(level), level_picture(mesh), ""});
      if (numbers) {
        const std::string said = cube_numbers(*mesh);
        if (!said.empty()) figure.numbers.push_back("level " + std::to_string(level) + ": " + said);
      }
    }
    const std::string words = difference_words(report);
    if (!words.empty()) {
      figure.problem = "level " + std::to_string(level) + ": " + words;
      break;
    }
  }
  return figure;
}

}  // namespace

WriteupPart upsample_part(const Submission& submission, const WriteupSettings& settings) {
  WriteupPart part;
  part.heading = "Part 6: Loop subdivision for mesh upsampling";
  part.task =
      "upsample(mesh) splits every edge, flips the new edges that join an old and a new vertex, and moves "
      "every vertex by Loop's weights.";
  const PartCode code = load_part_code(submission, Exercise::Upsample);
  const int levels = settings.levels;

  WriteupFigure cube;
  cube.number = "6.1";
  cube.caption = "The cube after " + std::to_string(levels) +
                 " levels of your upsample (the numbers: how evenly its "
                 "corners round off)";
  part.figures.push_back(upsampled(code, cube_mesh(), levels, std::move(cube), true));

  WriteupFigure symmetric;
  symmetric.number = "6.2";
  symmetric.caption = "The cube with each face's diagonal split first, after the same levels";
  part.figures.push_back(upsampled(code, cube_split(true), levels, std::move(symmetric), true));

  WriteupFigure sharp;
  sharp.number = "6.3";
  sharp.caption = "The cube with every edge split first, after the same levels (more vertices near its corners)";
  part.figures.push_back(upsampled(code, cube_split(false), levels, std::move(sharp), true));

  WriteupFigure teapot;
  teapot.number = "6.4";
  teapot.caption = "The teapot after one level of your upsample";
  std::shared_ptr<HalfedgeMesh> mesh;
  try {
    mesh = teapot_mesh(kTeapotResolution);
  } catch (const std::exception& e) {
    teapot.problem = e.what();
  }
  if (mesh) {
    part.figures.push_back(upsampled(code, mesh, 1, std::move(teapot), false));
  } else {
    part.figures.push_back(std::move(teapot));
  }
  part.questions = {
      "How does your upsample work, phase by phase, and what helped you find its mistakes?",
      "What happens to sharp corners and edges under subdivision, and how does splitting edges first change that?",
      "Why does the cube become asymmetric, and which flips or splits beforehand make it subdivide symmetrically?"};
  return part;
}

}  // namespace meshedit
