// "Mine vs reference": the catalogue; the templates in scripts/student are reported as different with a
// message saying what is missing; every solution in tests/exercise/solutions is identical to the reference on
// several inputs (cube, icosahedron, a grid with boundary, the teapot tessellated, several t and (u, v));
// buggy variants of the solutions (mistakes students really make) are caught with messages that name the mistake;
// loading, errors, limits, printing and the edit recording behave as exercises.h says.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                                student_file, solution_file, variant (a solution with edits), from_text,
//                                          mesh_of, teapot, meshes, curves, text_of, starts_with
//   catalogue                              the six exercises in order, find_exercise, ExerciseInput::describe
//   templates                              the templates (scripts/student) define their function, reported different
//   correct solutions                      expect_identical; each solution identical to the reference on every input;
//                                          runs never change the input
//   buggy variants: curve, patch, normals  a dropped last point, swapped weights, too many points, u and v swapped,
//                                          unit, inward or unnormalised normals
//   buggy variants: flip and split         edge_where; forgotten face and vertex halfedges, a flipped boundary edge,
//                                          the other rotation, a split vertex in the wrong place or pointing across, a
//                                          wrong face, boundary edges left unsplit
//   buggy variants: upsample               wrong flips, none or some (counted, with their causes), integer division
//                                          (each weight blamed), positions written to the wrong vertices, splitting
//                                          that never ends
//   loading, errors, output, recording     functions from the returned table or globals, load and run errors, caps, a
//                                          normal that changes the mesh, print and recorded edits, refusals, bad input
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/bezier.h"
#include "core/edit_log.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/patch_tessellation.h"
#include "core/primitives.h"
#include "core/value_format.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

using Mesh = std::shared_ptr<const HalfedgeMesh>;

std::filesystem::path student_file(Exercise e) {
  return testing::source_dir() / "scripts" / "student" / exercise_info(e).file;
}
std::filesystem::path solution_file(Exercise e) {
  return testing::source_dir() / "tests" / "exercise" / "solutions" / exercise_info(e).file;
}

// The solution of `e` with `from` replaced by `to` (which must occur), saved under the exercise's file name
// in a fresh folder; returns the loaded code.
std::unique_ptr<StudentCode> variant(Exercise e, const std::vector<std::pair<std::string, std::string>>& edits,
                                     LuaLimits limits = {}) {
  std::string text = testing::read_text(solution_file(e));
  for (const auto& [from, to] : edits) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "not in the solution: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const auto path = testing::scratch_dir() / exercise_info(e).file;
  std::ofstream(path, std::ios::binary) << text;
  return load_student_file(path, limits);
}

std::unique_ptr<StudentCode> from_text(const std::string& name, const std::string& text, LuaLimits limits = {}) {
  const auto path = testing::scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return load_student_file(path, limits);
}

Mesh mesh_of(const PolygonMesh& p) { return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(p)); }

Mesh teapot(int resolution) {
  return mesh_of(tessellate_patches(read_bez(testing::source_dir() / "assets" / "teapot.bez"), resolution));
}

std::vector<Mesh> meshes() {
  return {mesh_of(make_cube()), mesh_of(make_icosahedron()), mesh_of(make_grid(3, 2)), mesh_of(make_tetrahedron())};
}

std::vector<std::vector<glm::dvec3>> curves() {
  std::vector<std::vector<glm::dvec3>> out;
  for (const char* name : {"curve_cubic.bzc", "curve_quartic.bzc"}) {
    std::vector<glm::dvec3> points;
    for (const auto& p : read_bzc(testing::source_dir() / "assets" / name).control_points) points.emplace_back(p, 0.0);
    out.push_back(points);
  }
  out.push_back({{1, 2, 3}, {-1, 0.5, 7}, {4, 4, 4}});
  out.push_back({{0.25, 0.5, 0}, {1, 1, 1}});
  return out;
}

std::string text_of(const ExerciseReport& r) {
  std::string s = r.summary();
  for (const auto& d : r.differences) s += "\n  " + d;
  for (const auto& n : r.notes) s += "\n  note: " + n;
  return s;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// ---- catalogue -------------------------------------------------------------------------------------

TEST(Exercises, CatalogueListsTheSixInOrder) {
  const auto all = builtin_exercises();
  ASSERT_EQ(all.size(), 6u);
  const char* files[] = {"curve.lua", "patch.lua", "normals.lua", "flip.lua", "split.lua", "upsample.lua"};
  const char* functions[] = {"evaluate_step", "evaluate", "vertex_normal", "flip_edge", "split_edge", "upsample"};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_STREQ(all[i].info().file, files[i]);
    EXPECT_STREQ(all[i].info().function, functions[i]);
    EXPECT_EQ(find_exercise(all[i].info().name), all[i]);
    EXPECT_EQ(find_exercise(files[i]), all[i]);
    EXPECT_EQ(find_exercise(functions[i]), all[i]);
  }
  EXPECT_FALSE(find_exercise("collapse").has_value());
  EXPECT_EQ(ExerciseInput::edge(mesh_of(make_cube()), EdgeId(5)).describe(Exercise::FlipEdge),
            "e5 of a mesh with 8 vertices and 12 faces");
  EXPECT_EQ(ExerciseInput::curve_step({{0, 0, 0}, {1, 0, 0}}, 0.25).describe(Exercise::CurveStep),
            "2 points, t = 0.25");
}

// ---- templates -------------------------------------------------------------------------------------

TEST(Exercises, TemplatesDefineTheFunctionAndAreReportedDifferent) {
  const Mesh cube = mesh_of(make_cube());
  const BezierPatch patch = read_bez(testing::source_dir() / "assets" / "teapot.bez")[5];
  const auto cubic = curves()[0];
  struct Case {
    Exercise exercise;
    ExerciseInput input;
    std::string first;
  };
  const HalfedgeMesh& c = *cube;
  const HalfedgeId h0 = c.halfedge(EdgeId(0)), h1 = c.twin(h0);
  const std::string turn = format_id(c.vertex(h0)) + "-" + format_id(c.vertex(h1)) + " becomes " +
                           format_id(c.vertex(c.next(c.next(h1)))) + "-" + format_id(c.vertex(c.next(c.next(h0))));
  const glm::dvec3 midpoint = (c.position(c.vertex(h0)) + c.position(c.vertex(h1))) * 0.5;
  const Case cases[] = {
      {Exercise::CurveStep, ExerciseInput::curve_step(cubic, 0.3),
       "evaluate_step returned nil; it must return a list of points"},
      {Exercise::PatchEvaluate, ExerciseInput::patch_point(patch, 0.3, 0.8),
       "evaluate returned nil; it must return a vec3"},
      {Exercise::VertexNormal, ExerciseInput::vertex(cube, VertexId(3)),
       "vertex_normal returned nil; it must return a vec3"},
      {Exercise::FlipEdge, ExerciseInput::edge(cube, EdgeId(0)),
       "your flip_edge changed nothing and returned nil; the reference flips e0 (" + turn + ")"},
      {Exercise::SplitEdge, ExerciseInput::edge(cube, EdgeId(0)),
       "your split_edge changed nothing and returned nil; the reference splits e0 at its midpoint " +
           format_position(midpoint)},
      {Exercise::Upsample, ExerciseInput::whole_mesh(cube),
       "your upsample changed nothing; the reference makes 48 faces out of 12"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(exercise_info(k.exercise).file);
    auto code = load_student_file(student_file(k.exercise));
    EXPECT_TRUE(code->defines(k.exercise));
    const ExerciseReport r = check_exercise(*code, k.exercise, k.input);
    EXPECT_FALSE(r.equal);
    EXPECT_FALSE(r.identical);
    ASSERT_FALSE(r.differences.empty());
    EXPECT_EQ(r.differences[0], k.first);
    EXPECT_EQ(r.summary(), "different: " + k.first);
  }
}

// ---- correct solutions -----------------------------------------------------------------------------

void expect_identical(StudentCode& code, Exercise e, const ExerciseInput& input) {
  SCOPED_TRACE(input.describe(e));
  const ExerciseReport r = check_exercise(code, e, input);
  EXPECT_TRUE(r.equal) << text_of(r);
  EXPECT_TRUE(r.identical) << text_of(r);
  EXPECT_TRUE(r.differences.empty()) << text_of(r);
  EXPECT_EQ(r.total_differences, 0u);
  EXPECT_EQ(r.summary(), "same as the reference");
  if (r.mine.validation) {
    EXPECT_TRUE(r.mine.validation->ok()) << r.mine.validation->summary();
  }
}

TEST(Exercises, CurveSolutionIsIdenticalForEveryT) {
  auto code = load_student_file(solution_file(Exercise::CurveStep));
  for (const auto& points : curves()) {
    for (double t : {0.0, 0.3, 0.5, 0.75, 1.0}) {
      expect_identical(*code, Exercise::CurveStep, ExerciseInput::curve_step(points, t));
    }
  }
  // Levels below the control points, and one point (an empty step).
  const auto cubic = curves()[0];
  const auto level1 = de_casteljau_step(std::span<const glm::dvec3>(cubic), 0.3);
  expect_identical(*code, Exercise::CurveStep, ExerciseInput::curve_step(level1, 0.3));
  expect_identical(*code, Exercise::CurveStep, ExerciseInput::curve_step({{1, 2, 0}}, 0.3));
  const ExerciseReport r = check_exercise(*code, Exercise::CurveStep, ExerciseInput::curve_step(cubic, 0.3));
  EXPECT_EQ(r.mine.points, de_casteljau_step(std::span<const glm::dvec3>(cubic), 0.3));
  EXPECT_EQ(r.mine.returned, "a list of 3 points");
}

TEST(Exercises, PatchSolutionIsIdenticalOnTeapotPatches) {
  auto code = load_student_file(solution_file(Exercise::PatchEvaluate));
  const auto patches = read_bez(testing::source_dir() / "assets" / "teapot.bez");
  for (int index : {0, 5, 13, 21, 30}) {
    for (auto [u, v] : {std::pair{0.3, 0.8}, {0.5, 0.25}, {0.0, 1.0}, {1.0, 0.6}, {0.5, 0.5}}) {
      expect_identical(*code, Exercise::PatchEvaluate, ExerciseInput::patch_point(patches[index], u, v));
    }
  }
}

TEST(Exercises, NormalsSolutionMatchesEveryVertex) {
  auto code = load_student_file(solution_file(Exercise::VertexNormal));
  std::vector<Mesh> inputs = meshes();
  inputs.push_back(teapot(2));
  for (const Mesh& mesh : inputs) {
    for (VertexId v : mesh->vertices()) {
      SCOPED_TRACE(format_id(v));
      const ExerciseReport r = check_exercise(*code, Exercise::VertexNormal, ExerciseInput::vertex(mesh, v));
      // The solution sums cross products from each triangle's corner at v; the core from the face's first
      // corner: equal up to rounding, not always bit for bit.
      EXPECT_TRUE(r.equal) << text_of(r);
      EXPECT_TRUE(r.differences.empty()) << text_of(r);
    }
  }
}

TEST(Exercises, FlipSolutionIsIdenticalOnEveryEdge) {
  auto code = load_student_file(solution_file(Exercise::FlipEdge));
  size_t refused = 0, flipped = 0;
  for (const Mesh& mesh : meshes()) {
    for (EdgeId e : mesh->edges()) {
      const ExerciseInput input = ExerciseInput::edge(mesh, e);
      expect_identical(*code, Exercise::FlipEdge, input);
      const ExerciseOutcome ref = run_reference(Exercise::FlipEdge, input);
      (ref.refused.empty() ? flipped : refused) += 1;
    }
  }
  // Boundary edges of the grid and every tetrahedron edge are refused; the rest flipped.
  EXPECT_GT(refused, 10u);
  EXPECT_GT(flipped, 40u);
}

TEST(Exercises, SplitSolutionIsIdenticalOnEveryEdgeBoundaryIncluded) {
  auto code = load_student_file(solution_file(Exercise::SplitEdge));
  for (const Mesh& mesh : meshes()) {
    for (EdgeId e : mesh->edges()) expect_identical(*code, Exercise::SplitEdge, ExerciseInput::edge(mesh, e));
  }
  // A second split on a mesh the first one changed (new elements present).
  auto split_once = std::make_shared<HalfedgeMesh>(*mesh_of(make_grid(2, 2)));
  const ExerciseReport first = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(split_once, EdgeId(4)));
  ASSERT_TRUE(first.identical) << text_of(first);
  const Mesh after = first.mine.mesh;
  for (EdgeId e : after->edges()) expect_identical(*code, Exercise::SplitEdge, ExerciseInput::edge(after, e));
}

TEST(Exercises, UpsampleSolutionIsIdenticalIncludingTheTeapot) {
  auto code = load_student_file(solution_file(Exercise::Upsample));
  std::vector<Mesh> inputs = meshes();
  inputs.push_back(teapot(3));
  for (const Mesh& mesh : inputs) expect_identical(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh));
  // Twice in a row (the second input has the first one's ids).
  const ExerciseReport once =
      check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_cube())));
  expect_identical(*code, Exercise::Upsample, ExerciseInput::whole_mesh(once.mine.mesh));
}

TEST(Exercises, RunsNeverChangeTheInput) {
  const Mesh cube = mesh_of(make_cube());
  const HalfedgeMesh copy = *cube;
  for (Exercise e : {Exercise::FlipEdge, Exercise::SplitEdge}) {
    auto code = load_student_file(solution_file(e));
    const ExerciseReport r = check_exercise(*code, e, ExerciseInput::edge(cube, EdgeId(2)));
    EXPECT_TRUE(r.equal);
    EXPECT_NE(r.mine.mesh.get(), cube.get());
    EXPECT_NE(r.reference.mesh.get(), r.mine.mesh.get());
  }
  auto code = load_student_file(solution_file(Exercise::Upsample));
  EXPECT_TRUE(check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(cube)).equal);
  EXPECT_TRUE(cube->same_as(copy));
}

// ---- buggy variants: curve, patch, normals ---------------------------------------------------------

TEST(Exercises, CurveStepDroppingTheLastPoint) {
  auto code = variant(Exercise::CurveStep, {{"for i = 1, #points - 1 do", "for i = 1, #points - 2 do"}});
  const ExerciseReport r = check_exercise(*code, Exercise::CurveStep, ExerciseInput::curve_step(curves()[0], 0.3));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_EQ(r.differences[0],
            "point 3 of the step is missing (got 2 points, expected 3): n points give n - 1, so "
            "the loop runs i = 1, ..., n - 1");
  EXPECT_EQ(r.total_differences, 1u) << text_of(r);
}

TEST(Exercises, CurveStepWithSwappedWeights) {
  auto code = variant(Exercise::CurveStep,
                      {{"(1 - t) * points[i] + t * points[i + 1]", "t * points[i] + (1 - t) * points[i + 1]"}});
  const ExerciseReport r = check_exercise(*code, Exercise::CurveStep, ExerciseInput::curve_step(curves()[0], 0.3));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_EQ(r.differences[0],
            "the weights are swapped: point i of the step must be (1 - t) * p_i + t * p_(i+1), "
            "and yours are t * p_i + (1 - t) * p_(i+1)");
  EXPECT_TRUE(starts_with(r.differences[1], "point 1 is (")) << text_of(r);
  // At t = 0.5 the swap cannot be seen, and is not reported.
  EXPECT_TRUE(check_exercise(*code, Exercise::CurveStep, ExerciseInput::curve_step(curves()[0], 0.5)).equal);
}

TEST(Exercises, CurveStepReturningTooMany) {
  auto code = from_text("curve.lua", "function evaluate_step(points, t) return points end");
  const ExerciseReport r = check_exercise(*code, Exercise::CurveStep, ExerciseInput::curve_step(curves()[0], 0.3));
  ASSERT_FALSE(r.differences.empty());
  EXPECT_EQ(r.differences[0],
            "the step has 4 points, expected 3: one step turns n points into n - 1 (yours has as "
            "many as it was given)");
}

TEST(Exercises, PatchWithColumnsFirst) {
  // Columns evaluated at u, then the row of results at v: the point at (v, u).
  auto code = variant(Exercise::PatchEvaluate,
                      {{"column[row + 1] = evaluate_1d({ p[base + 1], p[base + 2], p[base + 3], p[base + 4] }, u)",
                        "column[row + 1] = evaluate_1d({ p[row + 1], p[row + 5], p[row + 9], p[row + 13] }, u)"}});
  const BezierPatch patch = read_bez(testing::source_dir() / "assets" / "teapot.bez")[5];
  const ExerciseReport r = check_exercise(*code, Exercise::PatchEvaluate, ExerciseInput::patch_point(patch, 0.3, 0.8));
  EXPECT_FALSE(r.equal);
  ASSERT_EQ(r.differences.size(), 1u) << text_of(r);
  EXPECT_EQ(r.differences[0], "your point " + format_position(r.mine.points[0]) +
                                  " is the surface point at (u, v) = (0.8, 0.3), not (0.3, 0.8): u and v are swapped. "
                                  "Evaluate each row at u, then the column of the four row results at v");
}

TEST(Exercises, NormalsAveragingUnitFaceNormals) {
  auto code = variant(Exercise::VertexNormal,
                      {{"sum = sum + (p1 - p0):cross(p2 - p0)", "sum = sum + (p1 - p0):cross(p2 - p0):normalized()"}});
  // A fan of triangles with different areas (with equal areas the two answers agree).
  PolygonMesh uneven;
  uneven.add_vertex({0, 0, 0});
  uneven.add_vertex({1, 0, 0});
  uneven.add_vertex({0, 1, 0.5});
  uneven.add_vertex({-3, 0, 1});
  uneven.add_vertex({0, -1, 0});
  uneven.add_face({0, 1, 2});
  uneven.add_face({0, 2, 3});
  uneven.add_face({0, 3, 4});
  uneven.add_face({0, 4, 1});
  const ExerciseReport r =
      check_exercise(*code, Exercise::VertexNormal, ExerciseInput::vertex(mesh_of(uneven), VertexId(0)));
  EXPECT_FALSE(r.equal);
  ASSERT_EQ(r.differences.size(), 1u) << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[0], "your normal (")) << r.differences[0];
  EXPECT_NE(r.differences[0].find("is the average of the faces' unit normals; the reference ("), std::string::npos)
      << r.differences[0];
}

TEST(Exercises, NormalsInwardsAndNotNormalised) {
  auto inwards = variant(Exercise::VertexNormal, {{"(p1 - p0):cross(p2 - p0)", "(p2 - p0):cross(p1 - p0)"}});
  const Mesh ico = mesh_of(make_icosahedron());
  const ExerciseReport r = check_exercise(*inwards, Exercise::VertexNormal, ExerciseInput::vertex(ico, VertexId(4)));
  ASSERT_FALSE(r.differences.empty());
  EXPECT_NE(r.differences[0].find("points inwards"), std::string::npos) << text_of(r);
  auto unnormalised = variant(Exercise::VertexNormal, {{"return sum:normalized()", "return sum"}});
  const ExerciseReport s =
      check_exercise(*unnormalised, Exercise::VertexNormal, ExerciseInput::vertex(ico, VertexId(4)));
  ASSERT_FALSE(s.differences.empty());
  EXPECT_NE(s.differences[0].find("points the right way but has length"), std::string::npos) << text_of(s);
}

// ---- buggy variants: flip and split ----------------------------------------------------------------

// An interior edge whose h0 = e.halfedge is also a.halfedge (so forgetting a.halfedge breaks validity), or
// one whose f0.halfedge is h2 = h0.next (which the flip moves to f1, so forgetting f0.halfedge does).
EdgeId edge_where(const HalfedgeMesh& m, bool vertex_points_at_h0) {
  for (EdgeId e : m.edges()) {
    const HalfedgeId h0 = m.halfedge(e);
    if (m.is_boundary(e)) continue;
    if (vertex_points_at_h0 && m.halfedge(m.vertex(h0)) == h0) return e;
    if (!vertex_points_at_h0 && m.halfedge(m.face(h0)) == m.next(h0)) return e;
  }
  return EdgeId();
}

TEST(Exercises, FlipForgettingTheFacesHalfedge) {
  auto code = variant(Exercise::FlipEdge, {{"  f0.halfedge = h0\n  f1.halfedge = h1\n", ""}});
  const Mesh ico = mesh_of(make_icosahedron());
  const EdgeId e = edge_where(*ico, false);
  ASSERT_TRUE(e.valid());
  const ExerciseReport r = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(ico, e));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  const FaceId f0 = ico->face(ico->halfedge(e));
  EXPECT_TRUE(starts_with(r.differences[0], "after your flip_edge the mesh is not valid (")) << text_of(r);
  const std::string h2 = format_id(ico->next(ico->halfedge(e)));
  EXPECT_NE(r.differences[0].find(format_id(f0) + ".halfedge is " + h2 + ", but " + h2 + ".face is f"),
            std::string::npos)
      << text_of(r);
  EXPECT_FALSE(r.mine.validation->ok());
}

TEST(Exercises, FlipForgettingTheVerticesHalfedge) {
  auto code = variant(Exercise::FlipEdge, {{"  if a.halfedge == h0 then a.halfedge = h4 end\n", ""}});
  const Mesh cube = mesh_of(make_cube());
  const EdgeId e = edge_where(*cube, true);
  ASSERT_TRUE(e.valid());
  const VertexId a = cube->vertex(cube->halfedge(e));
  const ExerciseReport r = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(cube, e));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  const std::string h0 = format_id(cube->halfedge(e));
  EXPECT_TRUE(starts_with(r.differences[0], "after your flip_edge the mesh is not valid (")) << text_of(r);
  EXPECT_NE(r.differences[0].find(format_id(a) + ".halfedge is " + h0 + ", but " + h0 + " leaves v"), std::string::npos)
      << text_of(r);
}

TEST(Exercises, FlipOfABoundaryEdge) {
  auto code = variant(Exercise::FlipEdge, {{"  if f0:is_boundary() or f1:is_boundary() then return nil end\n", ""},
                                           {"  if f0:degree() ~= 3 or f1:degree() ~= 3 then return nil end\n", ""},
                                           {"  if c == d then return nil end\n", ""},
                                           {"    if w == d then return nil end  -- c-d is already an edge\n", ""}});
  const Mesh grid = mesh_of(make_grid(3, 2));
  EdgeId boundary;
  for (EdgeId e : grid->edges()) {
    if (grid->is_boundary(e) && !grid->face(grid->halfedge(e)).is_boundary()) {
      boundary = e;
      break;
    }
  }
  ASSERT_TRUE(boundary.valid());
  const ExerciseReport r = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(grid, boundary));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty()) << text_of(r);
  const std::string reason = r.reference.refused;
  EXPECT_NE(reason.find("boundary"), std::string::npos) << reason;
  EXPECT_TRUE(starts_with(r.differences[0], "the reference does not flip " + format_id(boundary) + " (" + reason +
                                                "), but your flip_edge changed the mesh: "))
      << text_of(r);
  // Interior edges still flip correctly with this variant.
  EXPECT_TRUE(
      check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(mesh_of(make_cube()), EdgeId(3))).identical);
}

TEST(Exercises, FlipWithTheOtherRotationIsEqualButNotIdentical) {
  // Turning the edge clockwise (a-b becomes c-d with h0 running c->d) is a correct flip with other pointers.
  auto code = from_text("flip.lua", R"lua(
function flip_edge(mesh, e)
  local h0 = e.halfedge
  local h1 = h0.twin
  local f0, f1 = h0.face, h1.face
  if f0:is_boundary() or f1:is_boundary() then return nil end
  local h2, h4 = h0.next, h1.next
  local h3, h5 = h2.next, h4.next
  local a, b, c, d = h0.vertex, h1.vertex, h3.vertex, h5.vertex
  -- f0 = (c, d, b): h0 c->d, h5 d->b, h2 b->c;  f1 = (d, c, a): h1 d->c, h3 c->a, h4 a->d
  h0:set_neighbors(h5, h1, c, e, f0)
  h5.next = h2; h5.face = f0; h2.next = h0
  h1:set_neighbors(h3, h0, d, e, f1)
  h3.next = h4; h3.face = f1; h4.next = h1
  f0.halfedge = h0; f1.halfedge = h1
  if a.halfedge == h0 then a.halfedge = h4 end
  if b.halfedge == h1 then b.halfedge = h2 end
  return e
end
)lua");
  const ExerciseReport r =
      check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(mesh_of(make_cube()), EdgeId(3)));
  EXPECT_TRUE(r.equal) << text_of(r);
  EXPECT_FALSE(r.identical);
  ASSERT_EQ(r.notes.size(), 1u) << text_of(r);
  EXPECT_TRUE(starts_with(r.notes[0], "a correct flip of e3 (")) << r.notes[0];
}

TEST(Exercises, SplitAtTheAverageOfTheFourCorners) {
  auto code =
      variant(Exercise::SplitEdge, {{"mesh:new_vertex((a.position + b.position) * 0.5)",
                                     "mesh:new_vertex((a.position + b.position + c.position + d.position) * 0.25)"}});
  const Mesh ico = mesh_of(make_icosahedron());
  const ExerciseReport r = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(ico, EdgeId(7)));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  const std::string m = format_id(r.mine.element);
  EXPECT_EQ(m, "v12");
  EXPECT_TRUE(starts_with(r.differences[0], "your new vertex v12 is at (")) << text_of(r);
  EXPECT_NE(r.differences[0].find(", the average of the corners v"), std::string::npos) << text_of(r);
  EXPECT_NE(r.differences[0].find("; it belongs at the midpoint of v"), std::string::npos) << text_of(r);
}

TEST(Exercises, SplitWithAWrongFaceOnANewHalfedge) {
  auto code =
      variant(Exercise::SplitEdge, {{"n3:set_neighbors(h0, n2, c, ec, f0)", "n3:set_neighbors(h0, n2, c, ec, g0)"}});
  const Mesh cube = mesh_of(make_cube());
  const ExerciseReport r = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(cube, EdgeId(2)));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_TRUE(starts_with(r.differences[0], "after your split_edge the mesh is not valid (")) << text_of(r);
  // n3 is the fourth new halfedge: its id is the old halfedge count + 3.
  const std::string n3 = "h" + std::to_string(cube->halfedge_capacity() + 3);
  EXPECT_NE(text_of(r).find(n3 + ".face is f"), std::string::npos) << text_of(r);
}

TEST(Exercises, SplitWhoseVertexPointsAcross) {
  auto code = variant(Exercise::SplitEdge, {{"  m.halfedge = n1\n", "  m.halfedge = n2\n"}});
  const ExerciseReport r =
      check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(mesh_of(make_cube()), EdgeId(2)));
  EXPECT_FALSE(r.equal);
  ASSERT_EQ(r.differences.size(), 1u) << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[0], "v8.halfedge is h")) << text_of(r);
  EXPECT_NE(r.differences[0].find("across a face; the new vertex's halfedge must run along the split edge"),
            std::string::npos);
}

TEST(Exercises, SplitIgnoringBoundaryEdgesIsToldTheReferenceSplitsThem) {
  auto code = variant(Exercise::SplitEdge, {{"  local boundary = f1:is_boundary()\n",
                                             "  if f1:is_boundary() then return nil end\n  local boundary = false\n"}});
  const Mesh grid = mesh_of(make_grid(1, 1));
  const ExerciseReport r = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(grid, EdgeId(0)));
  ASSERT_FALSE(r.differences.empty());
  EXPECT_EQ(r.differences[0],
            "your split_edge changed nothing and returned nil; the reference splits e0 at its "
            "midpoint (0.5, 0, 0) (a boundary edge: only the triangle side is split; extra credit "
            "in the course)");
}

// ---- buggy variants: upsample ----------------------------------------------------------------------

TEST(Exercises, UpsampleFlippingWithOneEndpointCheck) {
  auto code =
      variant(Exercise::Upsample,
              {{"if (is_new[x.id] == true) ~= (is_new[y.id] == true) then", "if is_new[x.id] or is_new[y.id] then"}});
  const ExerciseReport r =
      check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_icosahedron())));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  // Flipping new edges with two new ends leaves edges between two original vertices, which no correct
  // subdivision has.
  EXPECT_NE(r.differences[0].find(" of your edges join two original vertices, e.g. e"), std::string::npos)
      << text_of(r);
  EXPECT_NE(r.differences[0].find("a new edge whose ends were both new was flipped"), std::string::npos) << text_of(r);
}

TEST(Exercises, UpsampleNotFlippingAtAll) {
  auto code = variant(Exercise::Upsample, {{"then mesh:flip(e) end", "then end"}});
  const ExerciseReport r = check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_cube())));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  // The cube: 18 edges, 12 faces; each face's cross edge that should have been flipped stays. Nothing flipped: marks
  // that never match are the likeliest cause, then the one-way test (flags on the halves would have flipped halves).
  EXPECT_TRUE(starts_with(r.differences[0],
                          "your upsample flipped none of the 12 new edges the reference flips: 12 of your edges "
                          "still join an original and a new vertex across an old face, e.g. e"))
      << text_of(r);
  const std::string& d = r.differences[0];
  const size_t marks = d.find(
                   "The usual causes, most likely first: the marks never match (a table keyed by the "
                   "handle"),
               one_way = d.find("; the old/new test accepts one order only"),
               flags = d.find("; or the flags were set on the wrong edges");
  EXPECT_NE(marks, std::string::npos) << d;
  EXPECT_LT(marks, one_way) << d;
  EXPECT_NE(flags, std::string::npos) << d;
  EXPECT_LT(one_way, flags) << d;
}

TEST(Exercises, UpsampleMarkingNewEdgesByHandle) {
  // A table keyed by the handle: every read of e makes another handle, so new_edge[e] never finds the mark.
  auto code = variant(Exercise::Upsample, {{"new_edge[h.edge.id] = true", "new_edge[h.edge] = true"},
                                           {"if new_edge[e.id] then", "if new_edge[e] then"}});
  const ExerciseReport r =
      check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_icosahedron())));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_TRUE(starts_with(r.differences[0],
                          "your upsample flipped none of the 20 new edges the reference flips: 20 "
                          "of your edges still join an original and a new vertex"))
      << text_of(r);
  EXPECT_NE(r.differences[0].find("key them by e.id and m.id"), std::string::npos) << text_of(r);
}

TEST(Exercises, UpsampleFlippingOnlySomeNewEdges) {
  // Half the flips made: counted from the connectivity, with the one-way test as the likeliest cause.
  auto code = variant(Exercise::Upsample, {{"if new_edge[e.id] then", "if new_edge[e.id] and e.id % 2 == 0 then"}});
  const ExerciseReport r = check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_cube())));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  const std::string& d = r.differences[0];
  EXPECT_TRUE(starts_with(d, "your upsample flipped ")) << text_of(r);
  EXPECT_EQ(d.find("your upsample flipped none"), std::string::npos) << d;
  EXPECT_NE(d.find(" of the 12 new edges the reference flips: "), std::string::npos) << d;
  EXPECT_NE(d.find("The usual causes, most likely first: the old/new test accepts one order only (a old and b new, "
                   "but not a new and b old"),
            std::string::npos)
      << d;
}

TEST(Exercises, UpsampleWithIntegerDivision) {
  auto code =
      variant(Exercise::Upsample, {{"(n == 3) and 3 / 16 or 3 / (8 * n)", "(n == 3) and 3 // 16 or 3 // (8 * n)"},
                                   {"3 / 8 * (a + b) + 1 / 8 * (c + d)", "3 // 8 * (a + b) + 1 // 8 * (c + d)"}});
  const ExerciseReport r =
      check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_icosahedron())));
  EXPECT_FALSE(r.equal);
  ASSERT_GE(r.differences.size(), 2u) << text_of(r);
  // The weights are blamed, not step 5: the new vertices moved (to the origin), so step 5 ran.
  EXPECT_EQ(r.differences[0],
            "your weight u is 0 for degrees other than 3 (in Lua 3 // (8 * n) is 0, an integer division: write "
            "3 / (8 * n)): 12 of the 12 original vertices kept their old positions while your new vertices moved; an "
            "original vertex moves to (1 - n u) p + u (sum of the neighbours), u = 3/16 for degree 3, else 3 / (8 n) "
            "(if your u is not 0, step 5 must move the original vertices too)");
  EXPECT_TRUE(starts_with(r.differences[1],
                          "your edge weights 3/8 and 1/8 are 0 (in Lua 3 // 8 and 1 // 8 are 0, integer divisions: "
                          "write 3 / 8 and 1 / 8): 30 of your new vertices, e.g. v12 on the edge v"))
      << text_of(r);
  EXPECT_EQ(text_of(r).find("step 5 must move them to the positions of step 1"), std::string::npos) << text_of(r);
  EXPECT_EQ(text_of(r).find("a weight that should not be zero"), std::string::npos) << text_of(r);
}

TEST(Exercises, UpsampleWithOneIntegerDivisionWeight) {
  // Only the branch for degrees other than 3: on a triangular bipyramid the two poles (degree 3) move right, the three
  // vertices of the equator (degree 4) stay.
  PolygonMesh bipyramid;
  for (const glm::dvec3& p : {glm::dvec3(0, 0, 1.5), glm::dvec3(1, 0, 0), glm::dvec3(-0.4, 1, 0.1),
                              glm::dvec3(-0.6, -0.9, 0), glm::dvec3(0.1, 0, -1)}) {
    bipyramid.add_vertex(p);
  }
  for (const auto& f :
       std::vector<std::vector<uint32_t>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {4, 2, 1}, {4, 3, 2}, {4, 1, 3}}) {
    bipyramid.add_face(f);
  }
  auto u = variant(Exercise::Upsample, {{"3 / (8 * n)", "3 // (8 * n)"}});
  const ExerciseReport r = check_exercise(*u, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(bipyramid)));
  ASSERT_FALSE(r.differences.empty());
  EXPECT_TRUE(starts_with(r.differences[0],
                          "your weight u is 0 for degrees other than 3 (in Lua 3 // (8 * n) is 0, an integer "
                          "division: write 3 / (8 * n)): 3 of the 5 original vertices kept their old positions"))
      << text_of(r);
  // The edge's 1/8 alone: the new vertices sit at 3/8 (a + b).
  auto eighth = variant(Exercise::Upsample, {{"1 / 8 * (c + d)", "1 // 8 * (c + d)"}});
  const ExerciseReport s =
      check_exercise(*eighth, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_icosahedron())));
  ASSERT_FALSE(s.differences.empty());
  EXPECT_TRUE(starts_with(s.differences[0],
                          "your edge weight 1/8 is 0 (in Lua 1 // 8 is 0, an integer division: write 1 / 8): 30 of "
                          "your new vertices, e.g. v12 on the edge v"))
      << text_of(s);
  EXPECT_NE(s.differences[0].find(", are at 3/8 (a + b) instead of 3/8 (a + b) + 1/8 (c + d)"), std::string::npos)
      << text_of(s);
}

TEST(Exercises, UpsampleWithIntegerDivisionOnTheBoundary) {
  auto code =
      variant(Exercise::Upsample, {{"0.75 * p + 0.125 * (rim[1] + rim[2])", "3 // 4 * p + 0.125 * (rim[1] + rim[2])"},
                                   {"edge_position[e.id] = 0.5 * (a + b)", "edge_position[e.id] = 1 // 2 * (a + b)"}});
  // The grid's corner v0 is at the origin, where 1/8 (a + b) is the course's position too: the other 7 are named.
  const ExerciseReport r =
      check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_grid(2, 2))));
  ASSERT_GE(r.differences.size(), 2u) << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[0],
                          "your boundary vertex weight 3/4 is 0 (in Lua 3 // 4 is 0, an integer division: write "
                          "3 / 4): 7 of your boundary vertices, e.g. v1, are at 1/8 (a + b) instead of 3/4 p + 1/8 "
                          "(a + b)"))
      << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[1],
                          "your boundary edge weight 1/2 is 0 (in Lua 1 // 2 is 0, an integer division: write 1 / 2): "
                          "8 of your new vertices on boundary edges, e.g. v"))
      << text_of(r);
}

TEST(Exercises, UpsampleWritingPositionsToTheWrongVertices) {
  // Every vertex gets the position computed for vertex 0 (a loop variable mix-up): the mesh collapses.
  auto code = variant(Exercise::Upsample, {{"v.position = new_position[v.id]", "v.position = new_position[0]"}});
  const ExerciseReport r = check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_cube())));
  EXPECT_FALSE(r.equal);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_NE(text_of(r).find("of your vertices sit exactly on another one: were new positions written to the wrong "
                            "vertices?"),
            std::string::npos)
      << text_of(r);
}

TEST(Exercises, UpsampleSplittingNewEdgesNeverEnds) {
  LuaLimits limits;
  limits.instructions = 1'000'000;
  auto code = variant(Exercise::Upsample,
                      {{"  for _, e in ipairs(originals) do\n",
                        "  local i = 0\n  while i < mesh:num_edges() do\n    local e = mesh:edge(i)\n    i = i + 1\n"}},
                      limits);
  const ExerciseReport r = check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh_of(make_cube())));
  EXPECT_FALSE(r.equal);
  EXPECT_FALSE(r.mine.ran);
  ASSERT_EQ(r.differences.size(), 2u) << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[0], "upsample.lua:")) << text_of(r);
  // Stopped by the recording's budget (upsample_runaway.h), well before the instruction budget.
  EXPECT_NE(r.differences[0].find(" changes recorded; is there a loop that never ends? It was stopped in phase 2 "
                                  "(edges split) after "),
            std::string::npos)
      << r.differences[0];
  EXPECT_NE(r.differences[0].find("; the mesh had 18 edges and Loop subdivision splits each of them once"),
            std::string::npos)
      << r.differences[0];
  EXPECT_TRUE(starts_with(r.differences[1], "upsample did not finish: split only the edges of the original mesh"));
}

// ---- loading, errors, output, recording ------------------------------------------------------------

TEST(Exercises, FunctionsMayComeFromTheReturnedTableOrGlobals) {
  const auto input = ExerciseInput::curve_step(curves()[0], 0.3);
  auto table_only = from_text("curve.lua",
                              "local function step(points, t) local r = {} for i = 1, #points - 1 do "
                              "r[i] = (1 - t) * points[i] + t * points[i + 1] end return r end "
                              "return { evaluate_step = step }");
  EXPECT_TRUE(check_exercise(*table_only, Exercise::CurveStep, input).identical);
  lua_State* L = table_only->runtime().state();
  EXPECT_EQ(lua_getglobal(L, "evaluate_step"), LUA_TNIL);
  lua_pop(L, 1);
  auto nothing = from_text("curve.lua", "x = 1");
  EXPECT_FALSE(nothing->defines(Exercise::CurveStep));
  const ExerciseReport r = check_exercise(*nothing, Exercise::CurveStep, input);
  EXPECT_EQ(r.differences,
            std::vector<std::string>{
                "your code does not define evaluate_step (as a global or in the table curve.lua returns)"});
  // Two files in one runtime: upsample can call a flip_edge defined by flip.lua.
  StudentCode both;
  both.load(solution_file(Exercise::FlipEdge));
  both.load(solution_file(Exercise::Upsample));
  EXPECT_TRUE(both.defines(Exercise::FlipEdge));
  EXPECT_TRUE(both.defines(Exercise::Upsample));
  EXPECT_FALSE(both.defines(Exercise::SplitEdge));
}

TEST(Exercises, LoadErrorsNameTheFileAndLine) {
  const auto error_of = [](const std::string& text) {
    try {
      from_text("flip.lua", text);
    } catch (const ScriptError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of("function flip_edge(mesh, e)\n  return e +\nend\n"), "flip.lua:3: unexpected symbol near 'end'");
  EXPECT_EQ(error_of("local x = nil\nx.y = 1\n"), "flip.lua:2: attempt to index a nil value (local 'x')");
  EXPECT_EQ(error_of("error('no', 0)"), "no");
  try {
    load_student_file(testing::scratch_dir() / "missing.lua");
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_TRUE(starts_with(e.what(), "cannot open ")) << e.what();
  }
}

TEST(Exercises, ErrorsDuringTheCallBecomeTheFirstDifference) {
  auto code = from_text("flip.lua",
                        "function flip_edge(mesh, e)\n  local h = e.halfedge.next.next.next.face\n"
                        "  return h.nothing.twin\nend\n");
  const ExerciseReport r =
      check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(mesh_of(make_cube()), EdgeId(0)));
  EXPECT_FALSE(r.mine.ran);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_TRUE(starts_with(r.differences[0], "flip.lua:3: ")) << text_of(r);
  // A loop that never ends inside pcall is still stopped, with the hint about walks.
  LuaLimits limits;
  limits.instructions = 1'000'000;
  auto endless = from_text("normals.lua",
                           "function vertex_normal(v)\n  local h = v.halfedge\n"
                           "  repeat pcall(function() h = h.next end) until false\nend\n",
                           limits);
  const ExerciseReport s =
      check_exercise(*endless, Exercise::VertexNormal, ExerciseInput::vertex(mesh_of(make_cube()), VertexId(0)));
  ASSERT_EQ(s.differences.size(), 2u) << text_of(s);
  EXPECT_NE(s.differences[0].find("instruction budget exceeded"), std::string::npos);
  EXPECT_TRUE(starts_with(s.differences[1], "it did not finish: a walk like"));
  // The runtime is usable again afterwards.
  EXPECT_TRUE(endless->defines(Exercise::VertexNormal));
}

// A run stopped by a cap on what a script may make (here the recording's) is told like one stopped by a limit, with the
// hint; a script raising the same words itself is an ordinary error: the runtime types the stop, the text does not.
TEST(Exercises, ACapStopsTheRunButTheSameWordsRaisedByTheScriptDoNot) {
  const auto input = ExerciseInput::edge(mesh_of(make_cube()), EdgeId(0));
  RunOptions recorded;
  recorded.record_edits = true;
  recorded.max_edits = 10;
  auto runaway = from_text("flip.lua", "function flip_edge(mesh, e)\n  while true do mesh:new_vertex() end\nend\n");
  const ExerciseReport r = check_exercise(*runaway, Exercise::FlipEdge, input, recorded);
  EXPECT_EQ(r.mine.limit, ScriptError::Limit::Changes);
  ASSERT_EQ(r.differences.size(), 2u) << text_of(r);
  EXPECT_EQ(r.differences[0], "flip.lua:2: more than 10 changes recorded; is there a loop that never ends?");
  EXPECT_EQ(r.differences[1], unfinished_run_hint(Exercise::FlipEdge));
  auto says_so = from_text("flip.lua",
                           "function flip_edge(mesh, e)\n  error('scripts may make at most 3; more than 10 "
                           "changes recorded')\nend\n");
  const ExerciseReport s = check_exercise(*says_so, Exercise::FlipEdge, input, recorded);
  EXPECT_EQ(s.mine.limit, ScriptError::Limit::None);
  EXPECT_EQ(s.differences, std::vector<std::string>{"flip.lua:2: scripts may make at most 3; more than 10 changes "
                                                    "recorded"});
}

TEST(Exercises, NormalThatChangesTheMeshIsReported) {
  auto code = variant(Exercise::VertexNormal,
                      {{"  return sum:normalized()", "  v.position = v.position * 2\n  return sum:normalized()"}});
  const ExerciseReport r =
      check_exercise(*code, Exercise::VertexNormal, ExerciseInput::vertex(mesh_of(make_cube()), VertexId(1)));
  EXPECT_FALSE(r.equal);
  ASSERT_EQ(r.differences.size(), 1u) << text_of(r);
  EXPECT_TRUE(starts_with(r.differences[0], "vertex_normal changed the mesh: v1.position was (")) << text_of(r);
}

TEST(Exercises, PrintIsCapturedAndEditsAreRecordedForReplay) {
  auto code = variant(Exercise::FlipEdge,
                      {{"  local h2 = h0.next\n", "  print('flipping', tostring(e))\n  local h2 = h0.next\n"}});
  const Mesh cube = mesh_of(make_cube());
  RunOptions options;
  options.record_edits = true;
  const ExerciseReport r = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(cube, EdgeId(4)), options);
  EXPECT_TRUE(r.identical) << text_of(r);
  EXPECT_EQ(r.mine.output, std::vector<std::string>{"flipping\te4"});
  ASSERT_FALSE(r.mine.edits.empty());
  EXPECT_TRUE(starts_with(r.mine.edits.front().where, "flip.lua:")) << r.mine.edits.front().where;
  const HalfedgeMesh replayed = replay(*cube, r.mine.edits, r.mine.edits.size());
  EXPECT_TRUE(replayed.same_as(*r.mine.mesh));
  // Without the option nothing is recorded.
  EXPECT_TRUE(check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(cube, EdgeId(4))).mine.edits.empty());
}

TEST(Exercises, RefusedByBothIsIdentical) {
  auto code = load_student_file(solution_file(Exercise::FlipEdge));
  const Mesh tetrahedron = mesh_of(make_tetrahedron());
  const ExerciseReport r = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(tetrahedron, EdgeId(0)));
  EXPECT_FALSE(r.reference.refused.empty());
  EXPECT_TRUE(r.identical) << text_of(r);
  EXPECT_EQ(r.mine.returned, "nil");
}

TEST(Exercises, BadInputThrows) {
  auto code = load_student_file(solution_file(Exercise::FlipEdge));
  const Mesh cube = mesh_of(make_cube());
  EXPECT_THROW(check_exercise(*code, Exercise::FlipEdge, ExerciseInput::vertex(cube, VertexId(0))), MeshError);
  EXPECT_THROW(check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(cube, EdgeId(99))), MeshError);
  EXPECT_THROW(run_reference(Exercise::Upsample, ExerciseInput{}), MeshError);
}

}  // namespace
}  // namespace meshedit
