// Parts 3 to 5 of the write-up: the teapot shaded flat and by the student's vertex_normal, and a mesh (a grid unless
// writeup.json names one) before and after the student's flips and splits, with the pointer table of one flip in the
// lesson's diagram names.
#include <exception>
#include <utility>

#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "grade/submission.h"
#include "io/mesh_file.h"
#include "writeup/internal/writeup_parts.h"

namespace meshedit {
namespace {

constexpr int kTeapotResolution = 8;

// "1 flip", "3 flips".
std::string count_of(size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// The grid's cell diagonals (an interior edge whose ends differ in x and in y), in id order; on a mesh with none,
// its interior edges.
std::vector<uint32_t> diagonals(const HalfedgeMesh& mesh) {
  std::vector<uint32_t> found, interior;
  for (const EdgeId e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const HalfedgeId h = mesh.halfedge(e);
    const glm::dvec3 d = mesh.position(mesh.vertex(h)) - mesh.position(mesh.vertex(mesh.twin(h)));
    interior.push_back(e.index);
    if (d.x != 0.0 && d.y != 0.0) found.push_back(e.index);
  }
  return found.empty() ? interior : found;
}

// `count` of the diagonals, spread out (the first, the middle, the last...), when the settings chose none.
std::vector<uint32_t> chosen_edges(const std::vector<uint32_t>& chosen, const HalfedgeMesh& mesh, size_t count) {
  if (!chosen.empty()) return chosen;
  const std::vector<uint32_t> all = diagonals(mesh);
  std::vector<uint32_t> picked;
  for (size_t i = 0; i < count && !all.empty(); ++i)
    picked.push_back(all[(all.size() - 1) * i / std::max<size_t>(1, count - 1)]);
  return picked;
}

MeshPicture picture_of(std::shared_ptr<const HalfedgeMesh> mesh, std::vector<ElementRef> marked) {
  MeshPicture picture;
  picture.mesh = std::move(mesh);
  picture.marked = std::move(marked);
  return picture;
}

// The operation `exercise` of the student on each edge in turn, from `start`; stops at the first that differs from
// the reference (its words in `problem`). The mesh after the last run, as the student left it.
struct EdgeRuns {
  std::shared_ptr<const HalfedgeMesh> mesh;
  std::vector<ElementRef> marked;  // each edge run, and the vertex a split returned
  std::string problem;
  std::vector<ExerciseReport> reports;
};

EdgeRuns run_on_edges(const PartCode& code, Exercise exercise, std::shared_ptr<const HalfedgeMesh> start,
                      const std::vector<uint32_t>& edges) {
  EdgeRuns runs;
  runs.mesh = std::move(start);
  if (!code.code) {
    runs.problem = code.problem;
    return runs;
  }
  const char* verb = exercise == Exercise::FlipEdge ? "flipping e" : "splitting e";
  for (const uint32_t e : edges) {
    if (!runs.mesh->alive(EdgeId(e))) {
      runs.problem = "e" + std::to_string(e) + " is not an edge of the mesh (writeup.json names it)";
      break;
    }
    ExerciseReport report;
    try {
      report = check_exercise(*code.code, exercise, ExerciseInput::edge(runs.mesh, EdgeId(e)));
    } catch (const std::exception& ex) {  // check_exercise promises not to throw; a bug must not stop the write-up
      report.mine.error = ex.what();
    }
    if (report.mine.mesh) runs.mesh = report.mine.mesh;
    runs.marked.push_back(ElementRef(EdgeId(e)));
    if (report.mine.element.valid() && report.mine.element.kind == ElementKind::Vertex) {
      runs.marked.push_back(report.mine.element);
    }
    const std::string words = difference_words(report);
    runs.reports.push_back(std::move(report));
    if (!words.empty()) {
      runs.problem = verb + std::to_string(e) + ": " + words;
      break;
    }
  }
  return runs;
}

// The lesson's names around edge e (lessons/4_edge_flip.lua), in its order: h0 = e.halfedge, h1 its twin, h2 and h3
// after h0, h4 and h5 after h1, h6 to h9 the twins of h2 to h5, a and b the ends of h0 and h1, c and d the far
// corners, f0 and f1 the faces. Empty off a pair of triangles.
std::vector<std::pair<std::string, ElementRef>> diagram_names(const HalfedgeMesh& mesh, EdgeId e) {
  std::vector<std::pair<std::string, ElementRef>> names;
  if (!mesh.alive(e) || mesh.is_boundary(e)) return names;
  const HalfedgeId h0 = mesh.halfedge(e), h1 = mesh.twin(h0);
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2), h4 = mesh.next(h1), h5 = mesh.next(h4);
  const HalfedgeId inner[] = {h0, h1, h2, h3, h4, h5};
  for (int i = 0; i < 6; ++i) names.emplace_back("h" + std::to_string(i), ElementRef(inner[i]));
  for (int i = 2; i < 6; ++i) names.emplace_back("h" + std::to_string(i + 4), ElementRef(mesh.twin(inner[i])));
  names.emplace_back("a", ElementRef(mesh.vertex(h0)));
  names.emplace_back("b", ElementRef(mesh.vertex(h1)));
  names.emplace_back("c", ElementRef(mesh.vertex(h3)));
  names.emplace_back("d", ElementRef(mesh.vertex(h5)));
  names.emplace_back("f0", ElementRef(mesh.face(h0)));
  names.emplace_back("f1", ElementRef(mesh.face(h1)));
  return names;
}

// The diagram's name of `element`, or its id for one the diagram does not name.
std::string named(const std::vector<std::pair<std::string, ElementRef>>& names, ElementRef element) {
  for (const auto& [name, named_element] : names) {
    if (named_element == element) return name;
  }
  return format_id(element);
}

// The pointers of h0..h5 before and after one flip, in the diagram's names of the mesh before it.
std::vector<std::vector<std::string>> flip_table(const HalfedgeMesh& before, const HalfedgeMesh& after, EdgeId e) {
  const auto names = diagram_names(before, e);
  std::vector<std::vector<std::string>> rows;
  if (names.empty()) return rows;
  rows.push_back(
      {"halfedge", "id", "next before", "next after", "vertex before", "vertex after", "face before", "face after"});
  for (size_t i = 0; i < 6; ++i) {
    const HalfedgeId h(names[i].second.index);
    auto field = [&](const HalfedgeMesh& mesh, int which) -> std::string {
      if (!mesh.alive(h)) return "(gone)";
      if (which == 0) return named(names, ElementRef(mesh.next(h)));
      if (which == 1) return named(names, ElementRef(mesh.vertex(h)));
      return named(names, ElementRef(mesh.face(h)));
    };
    std::vector<std::string> row = {names[i].first, format_id(ElementRef(h))};
    for (int which = 0; which < 3; ++which) {
      row.push_back(field(before, which));
      row.push_back(field(after, which));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string validity(const std::shared_ptr<const HalfedgeMesh>& mesh) {
  return "the mesh after them: " + validate(*mesh).summary();
}

std::vector<ElementRef> edge_refs(const std::vector<uint32_t>& edges) {
  std::vector<ElementRef> refs;
  for (const uint32_t e : edges) refs.push_back(ElementRef(EdgeId(e)));
  return refs;
}

// `mesh` with the chosen edges marked, and after the student's runs on them (what they ran marked), with the mesh's
// validity when every run agreed with the reference's.
WriteupFigure before_and_after(const std::string& number, const std::string& caption, const PartCode& code,
                               const std::shared_ptr<const HalfedgeMesh>& mesh, const std::vector<uint32_t>& edges,
                               const EdgeRuns& runs, const std::string& noun) {
  WriteupFigure figure;
  figure.number = number;
  figure.caption = caption;
  figure.made_by = code.made_by;
  figure.problem = runs.problem;
  figure.pictures.push_back({"before", picture_of(mesh, edge_refs(edges)), ""});
  figure.pictures.push_back({"after " + count_of(runs.reports.size(), noun), picture_of(runs.mesh, runs.marked), ""});
  if (runs.problem.empty()) figure.numbers.push_back(validity(runs.mesh));
  return figure;
}

}  // namespace

WriteupPart normals_part(const Submission& submission) {
  WriteupPart part;
  part.heading = "Part 3: Area-weighted vertex normals";
  part.task = "vertex_normal(v) is the unit sum of the normals of v's faces, each weighted by the face's area.";
  const PartCode code = load_part_code(submission, Exercise::VertexNormal);
  WriteupFigure figure;
  figure.number = "3.1";
  figure.caption = "The teapot with flat shading and with Phong shading from your vertex normals, from the same camera";
  figure.made_by = code.made_by;
  figure.problem = code.problem;
  std::shared_ptr<HalfedgeMesh> teapot;
  try {
    teapot = teapot_mesh(kTeapotResolution);
  } catch (const std::exception& e) {
    figure.problem = e.what();
  }
  MeshPicture flat, phong;
  flat.mesh = phong.mesh = teapot;
  flat.wireframe = phong.wireframe = false;
  phong.smooth = true;
  if (teapot && code.code) {
    phong.normals.assign(teapot->vertex_capacity(), glm::vec3(0.0f));  // zero: the flat normal (nothing of theirs)
    for (const VertexId v : teapot->vertices()) {
      const ExerciseInput input = ExerciseInput::vertex(teapot, v);
      const ExerciseOutcome mine = code.code->run(Exercise::VertexNormal, input);
      if (!mine.error.empty() || mine.points.empty()) {
        figure.problem = format_id(ElementRef(v)) + ": " +
                         (mine.error.empty() ? "vertex_normal returned " + mine.returned : mine.error);
        break;  // one error says it; the rest keep the flat normal
      }
      phong.normals[v.index] = glm::vec3(mine.points.front());
      const glm::dvec3 reference = vertex_normal(*teapot, v);
      if (figure.problem.empty() && !(glm::distance(mine.points.front(), reference) <= 1e-6)) {
        const std::string words = difference_words(check_exercise(*code.code, Exercise::VertexNormal, input));
        if (!words.empty()) figure.problem = words;
      }
    }
  }
  figure.pictures.push_back({"flat shading", flat, ""});
  figure.pictures.push_back({"Phong shading with your vertex_normal", phong, ""});
  part.figures.push_back(std::move(figure));
  part.questions = {"How does your vertex_normal weight the faces around a vertex, and why by area?"};
  return part;
}

std::shared_ptr<const HalfedgeMesh> edit_mesh(const WriteupSettings& settings, std::vector<std::string>& notes) {
  if (settings.mesh) {
    try {
      return std::make_shared<HalfedgeMesh>(build_halfedge_mesh(load_mesh(*settings.mesh)));
    } catch (const std::exception& e) {  // a file that does not open, a mesh that is not a manifold, memory
      notes.push_back(std::string(kWriteupSettingsFile) + ": \"mesh\": " + e.what() + "; parts 4 and 5 use the grid");
    }
  }
  return std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_grid(4, 3)));
}

WriteupPart flip_part(const Submission& submission, const WriteupSettings& settings,
                      const std::shared_ptr<const HalfedgeMesh>& mesh) {
  WriteupPart part;
  part.heading = "Part 4: Edge flip";
  part.task =
      "flip_edge(e) turns the edge between two triangles to join their other two corners, reassigning pointers.";
  const PartCode code = load_part_code(submission, Exercise::FlipEdge);
  const std::vector<uint32_t> edges = chosen_edges(settings.flip_edges, *mesh, 3);
  const EdgeRuns runs = run_on_edges(code, Exercise::FlipEdge, mesh, edges);

  WriteupFigure figure = before_and_after("4.1", "A mesh before and after your flips of the marked edges", code, mesh,
                                          edges, runs, "flip");
  if (!runs.reports.empty() && runs.reports.front().mine.mesh) {
    figure.table = flip_table(*mesh, *runs.reports.front().mine.mesh, EdgeId(edges.front()));
    figure.numbers.push_back(
        "the pointers of the first flip (e" + std::to_string(edges.front()) +
        ") in lesson 4's diagram names: h0 is e.halfedge, h1 its twin, a and b its ends, c and d the far corners");
  }
  part.figures.push_back(std::move(figure));
  part.questions = {"How does your flip_edge reassign the pointers, and what helped you find its mistakes?"};
  return part;
}

WriteupPart split_part(const Submission& submission, const WriteupSettings& settings,
                       const std::shared_ptr<const HalfedgeMesh>& mesh) {
  WriteupPart part;
  part.heading = "Part 5: Edge split";
  part.task = "split_edge(e) puts a new vertex at the edge's midpoint and joins it to the opposite corners.";
  part.questions = {
      "How does your split_edge make and connect the new elements, and what helped you find its mistakes?",
      "If your split_edge splits boundary edges, how does it?"};
  const PartCode code = load_part_code(submission, Exercise::SplitEdge);
  const PartCode flips = load_part_code(submission, Exercise::FlipEdge);
  const std::vector<uint32_t> edges = chosen_edges(settings.split_edges, *mesh, 2);
  const EdgeRuns splits = run_on_edges(code, Exercise::SplitEdge, mesh, edges);

  part.figures.push_back(before_and_after("5.1", "A mesh before and after your splits of the marked edges", code, mesh,
                                          edges, splits, "split"));

  // Splits, then flips of the edges the first split made that can be flipped: the mix the spec asks for.
  WriteupFigure mix;
  mix.number = "5.2";
  mix.caption = "The same mesh after your splits and then flips of edges the splits made";
  mix.made_by = code.made_by + " and " + flips.made_by;
  std::vector<uint32_t> new_edges;
  if (splits.problem.empty()) {
    for (const EdgeId e : splits.mesh->edges()) {
      if (e.index >= mesh->edge_capacity() && !splits.mesh->is_boundary(e) && new_edges.size() < 2) {
        new_edges.push_back(e.index);
      }
    }
  }
  const EdgeRuns mixed = splits.problem.empty() ? run_on_edges(flips, Exercise::FlipEdge, splits.mesh, new_edges)
                                                : EdgeRuns{splits.mesh, {}, splits.problem, {}};
  mix.problem = mixed.problem;
  mix.pictures.push_back({"after the splits", picture_of(splits.mesh, splits.marked), ""});
  const std::string flips_label =
      splits.problem.empty() ? "then " + count_of(mixed.reports.size(), "flip") : "no flips: the splits failed";
  mix.pictures.push_back({flips_label, picture_of(mixed.mesh, edge_refs(new_edges)), ""});
  if (mixed.problem.empty()) mix.numbers.push_back(validity(mixed.mesh));
  part.figures.push_back(std::move(mix));

  // A boundary edge: optional in the spec, so a split that leaves it alone is said, not failed.
  WriteupFigure boundary;
  boundary.number = "5.3";
  boundary.caption = "A boundary edge split (optional)";
  boundary.made_by = code.made_by;
  std::optional<uint32_t> edge;
  for (const EdgeId e : mesh->edges()) {
    if (mesh->is_boundary(e)) {
      edge = e.index;
      break;
    }
  }
  if (!edge) {
    boundary.numbers.push_back("the mesh has no boundary edge to split (a grid has: leave out \"mesh\")");
    boundary.pictures.push_back({"the mesh", picture_of(mesh, {}), ""});
    part.figures.push_back(std::move(boundary));
    return part;
  }
  const EdgeRuns on_boundary = run_on_edges(code, Exercise::SplitEdge, mesh, {*edge});
  const bool left_alone = !on_boundary.reports.empty() && !on_boundary.reports.front().mine.element.valid() &&
                          on_boundary.reports.front().mine.error.empty();
  if (left_alone) {
    boundary.numbers.push_back("your split_edge leaves boundary edges alone (the spec makes them optional)");
  } else {
    boundary.problem = on_boundary.problem;
  }
  boundary.pictures.push_back({"before", picture_of(mesh, {ElementRef(EdgeId(*edge))}), ""});
  boundary.pictures.push_back({"after", picture_of(on_boundary.mesh, on_boundary.marked), ""});
  part.figures.push_back(std::move(boundary));
  return part;
}

}  // namespace meshedit
