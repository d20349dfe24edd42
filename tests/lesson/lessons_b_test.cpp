// The part 4, 5, 6, 7 and "bring your own mesh" lessons: each runs headless with its answers file through every
// step (run_lesson_headless, as CI's `meshedit lesson --headless` does) and says the numbers the core gives;
// driven step by step on a HeadlessHost, the labels and highlights name the right elements, and each check
// waits until the mesh on screen really is right (a wrong edit leaves the step waiting).
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                            contains, lesson_path, run_headless (a lesson through every step), said,
//                                      colour_of, label_of, step_index, edit_screen, diamond
//   part 4: edge flip                  the transcript (changed fields, the forgetful flip, the fields a flip in a
//                                      big grid changes), the diagram's labels, the flip's check
//   part 5: edge split                 the transcript naming the new elements (a boundary split too), labels on the
//                                      screen mesh
//   part 6: Loop subdivision           the transcript's counts and distances, each phase's screen mesh, the Shift+L
//                                      step, the pre-split fix
//   part 7: Catmull-Clark subdivision  lesson_number, lesson_point, lesson_counts, quad_grid, edge_between; the
//                                      transcript's points, counts and levels; the arrow to the vertex point, the
//                                      linear and Catmull-Clark cubes side by side
//   bring your own mesh                bowtie, fin, flipped, all_three, refusal_of, expect_report; the transcript's
//                                      refusals, repairs, up axes and counts; subdividing the student's mesh
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/catmull_clark.h"
#include "core/history.h"
#include "core/linear_subdivision.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/mesh_repair.h"
#include "core/palette.h"
#include "core/primitives.h"
#include "core/triangulate.h"
#include "core/up_axis.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "io/file_up_axis.h"
#include "io/mesh_file.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::filesystem::path lesson_path(const std::string& name) {
  return testing::source_dir() / "lessons" / (name + ".lua");
}

// Runs lessons/NAME.lua headless with tests/lesson/lessons/NAME_answers.lua and the correct solutions as the student's
// folder (your_turn) and the exercises of scripts/exercises registered, as `meshedit lesson` registers them; expects
// every step to pass with every answer awaited and used. Returns the transcript.
std::string run_headless(const std::string& name, size_t steps) {
  EXPECT_EQ(load_exercise_folder(testing::source_dir() / "scripts" / "exercises"), std::vector<std::string>{});
  std::ostringstream out;
  const auto answers = testing::source_dir() / "tests" / "lesson" / "lessons" / (name + "_answers.lua");
  const HeadlessOutcome outcome = run_lesson_headless(lesson_path(name), answers, out, LessonRunner::default_limits(),
                                                      testing::source_dir() / "tests" / "exercise" / "solutions");
  const std::string text = out.str();
  EXPECT_EQ(outcome.failure, "") << text;
  EXPECT_EQ(outcome.steps, steps) << text;
  EXPECT_EQ(outcome.passed, steps) << text;
  EXPECT_FALSE(contains(text, "not awaited")) << text;
  EXPECT_FALSE(contains(text, "not used")) << text;
  EXPECT_FALSE(contains(text, "**")) << "markdown is printed as plain text";
  return text;
}

// Everything the current step said, joined.
std::string said(const LessonRunner& runner) {
  std::string all;
  for (const std::string& block : runner.said()) all += block + "\n";
  return all;
}

std::string colour_of(const HeadlessHost& host, ElementRef element) {
  const auto it = host.highlights().find(element);
  return it == host.highlights().end() ? "" : colour_hex(it->second);
}

std::string label_of(const HeadlessHost& host, ElementRef element) {
  const auto it = host.labels().find(element);
  return it == host.labels().end() ? "" : it->second;
}

size_t step_index(const LessonRunner& runner, const std::string& title) {
  const std::vector<std::string> titles = runner.step_titles();
  const auto it = std::find(titles.begin(), titles.end(), title);
  EXPECT_NE(it, titles.end()) << title;
  return static_cast<size_t>(it - titles.begin());
}

// Applies an edit to a copy of the screen mesh and puts it back, as the window's key would.
template <class Edit>
void edit_screen(HeadlessHost& host, Edit&& edit) {
  std::shared_ptr<HalfedgeMesh> mesh = host.current_mesh();
  ASSERT_TRUE(mesh);
  edit(*mesh);
  host.set_current_mesh(mesh);
}

// The diamond as the lessons build it: a, b, c, d = v0..v3, f0 = (a, b, c), f1 = (b, a, d).
HalfedgeMesh diamond() {
  PolygonMesh polygons;
  polygons.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  polygons.add_face({0, 1, 2});
  polygons.add_face({1, 0, 3});
  return build_halfedge_mesh(polygons);
}

// ---- part 4: edge flip -----------------------------------------------------------------------------

TEST(LessonsB, EdgeFlipPassesHeadlessAndListsTheChangedFields) {
  const std::string text = run_headless("4_edge_flip", 7);
  EXPECT_EQ(text.rfind("Part 4: Edge flip (4_edge_flip.lua, 7 steps)\n", 0), 0u) << text;
  EXPECT_TRUE(contains(text, "  > selection e0\n")) << text;
  EXPECT_TRUE(contains(text, "  > flip e0\n\n  Flipped. e now runs from d to c, and the mesh still passes validation."))
      << text;
  // The diagram's names for the ids the builder gives: h1 is stored as h3, h2 as h1, h3 as h2.
  EXPECT_TRUE(contains(text, "h0 is h0, h1 is h3, h2 is h1, h3 is h2, h4 is h4, h5 is h5.")) << text;
  // The diff, in the diagram's names: exactly the after-list of mesh_ops.h, and (the diamond's faces and a, b
  // pointing at the halfedges the flip moves) the four face and vertex pointers of the classic bug.
  EXPECT_TRUE(contains(text, "every field the flip changed (14 in all)")) << text;
  for (const char* line : {"- h0.next: h2 to h3", "- h0.vertex: a to d", "- h2.next: h3 to h1", "- h2.face: f0 to f1",
                           "- h3.next: h0 to h4", "- h1.next: h4 to h5", "- h1.vertex: b to c", "- h4.next: h5 to h0",
                           "- h4.face: f1 to f0", "- h5.next: h1 to h2", "- f0.halfedge: h2 to h0",
                           "- f1.halfedge: h4 to h1", "- a.halfedge: h0 to h4", "- b.halfedge: h1 to h2"}) {
    EXPECT_TRUE(contains(text, std::string("  ") + line + "\n")) << line << "\n" << text;
  }
  // The forgetful flip, as the validator reports it in the diagram's names.
  for (const char* line : {"- f0.halfedge is h2, but h2.face is f1", "- a.halfedge is h0, but h0 leaves d"}) {
    EXPECT_TRUE(contains(text, std::string("  ") + line + "\n")) << line << "\n" << text;
  }
  EXPECT_TRUE(contains(text, "> click h3: wrong: That is h1 = h0.twin")) << text;
}

// The lesson's big grid: 80 x 70 squares, each cut in two; its diagonal from the vertex at (40, 35) to (41, 36).
EdgeId big_grid_diagonal(const HalfedgeMesh& big) {
  for (EdgeId e : big.edges()) {
    glm::dvec3 p = big.position(big.vertex(big.halfedge(e))), q = big.position(big.vertex(big.twin(big.halfedge(e))));
    if (p.x > q.x) std::swap(p, q);
    if (p == glm::dvec3(40, 35, 0) && q == glm::dvec3(41, 36, 0)) return e;
  }
  return {};
}

TEST(LessonsB, EdgeFlipPassesHeadlessAskingHowManyFieldsAFlipInABigMeshChanges) {
  const std::string text = run_headless("4_edge_flip", 7);
  // What the core's flip of that diagonal changes, counted as the lesson counts it (m:diff), kind by kind.
  const HalfedgeMesh big = build_halfedge_mesh(make_grid(80, 70));
  HalfedgeMesh flipped = big;
  ASSERT_TRUE(flip(flipped, big_grid_diagonal(big)).ok());
  const std::vector<FieldChange> changes = diff(big, flipped);
  std::set<ElementRef> halfedges, vertices, faces;
  for (const FieldChange& c : changes) {
    if (c.element.kind == ElementKind::Halfedge) halfedges.insert(c.element);
    if (c.element.kind == ElementKind::Vertex) vertices.insert(c.element);
    if (c.element.kind == ElementKind::Face) faces.insert(c.element);
  }
  ASSERT_EQ(halfedges.size() + vertices.size() + faces.size(), 8u);  // the two triangles' own elements, no edge
  ASSERT_EQ(vertices.size(), 1u);
  ASSERT_EQ(faces.size(), 1u);
  const std::string count = std::to_string(changes.size());

  const std::string question =
      "  ? Flip the yellow edge: how many fields of the mesh change (a field is one pointer of one element, such as "
      "h0.next or f0.halfedge)?\n";
  EXPECT_TRUE(contains(text, "This grid has 11200 triangles (80 by 70 squares, each cut in two), 33900 halfedges."))
      << text;
  EXPECT_TRUE(contains(text, question)) << text;
  // Too few: what else a flip rewrites; about the mesh's size: that is a rebuild of the face list.
  EXPECT_TRUE(contains(text,
                       "  > answer 2: wrong: The diagonal's two halfedges change (h0.vertex and h1.vertex), but so "
                       "do the next pointers of all six halfedges of the two triangles"))
      << text;
  EXPECT_TRUE(contains(text,
                       "  > answer 33600: wrong: That is about every element: a rebuild of the face list rewrites "
                       "every face's corners (3 x 11200 = 33600 numbers)."))
      << text;
  EXPECT_TRUE(contains(text, "  > answer 10: right\n")) << text;
  // Then, and only then, the count the core gives, the elements, and the face list's 3 x 11200 corners.
  const std::string told = "The flip changed " + count +
                           " fields (each a field of one element whose value differs after the flip, as m:diff lists "
                           "them) of 8 elements: 6 halfedges, 1 vertex, 1 face, all in the two triangles at the edge "
                           "(orange); the other 11198 triangles keep every field.";
  EXPECT_TRUE(contains(text, told)) << text;
  EXPECT_TRUE(contains(text, "writes 3 corners of each of the 11200 faces, 33600 numbers, about " +
                                 std::to_string((33600 + changes.size() / 2) / changes.size()) + " times as many"))
      << text;
  EXPECT_LT(text.find(question), text.find(told));
  // The last step runs the student's flip on that edge of the big grid too: the solution is right there.
  EXPECT_TRUE(contains(text, "as the Exercises tab and the grader do.\n  > your turn flip.lua: right\n")) << text;
}

TEST(LessonsB, EdgeFlipLabelsEveryElementWithTheDiagramsName) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("4_edge_flip"))) << runner.error();
  // The first step asks the student to click h0.next, with every name already on screen.
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  const HalfedgeMesh mesh = diamond();
  const HalfedgeId h0 = mesh.halfedge(EdgeId(0));
  const HalfedgeId h1 = mesh.twin(h0), h2 = mesh.next(h0), h3 = mesh.next(h2), h4 = mesh.next(h1), h5 = mesh.next(h4);
  EXPECT_EQ(h1, HalfedgeId(3));
  EXPECT_EQ(h2, HalfedgeId(1));
  const std::pair<ElementRef, std::string> expected[] = {{VertexId(0), "a"},
                                                         {VertexId(1), "b"},
                                                         {VertexId(2), "c"},
                                                         {VertexId(3), "d"},
                                                         {FaceId(0), "f0"},
                                                         {FaceId(1), "f1"},
                                                         {h0, "h0"},
                                                         {h1, "h1"},
                                                         {h2, "h2"},
                                                         {h3, "h3"},
                                                         {h4, "h4"},
                                                         {h5, "h5"},
                                                         {mesh.twin(h2), "h6"},
                                                         {mesh.twin(h3), "h7"},
                                                         {mesh.twin(h4), "h8"},
                                                         {mesh.twin(h5), "h9"}};
  EXPECT_EQ(host.labels().size(), std::size(expected));
  for (const auto& [element, name] : expected) EXPECT_EQ(label_of(host, element), name) << format_id(element);
  EXPECT_TRUE(mesh.is_boundary(mesh.twin(h2)));
  EXPECT_EQ(colour_of(host, EdgeId(0)), colour_hex(kDarkSwatches.yellow));
}

TEST(LessonsB, EdgeFlipWaitsUntilTheEdgeReallyJoinsCAndD) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("4_edge_flip")));
  runner.go_to(step_index(runner, "Flip it yourself"));
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Selection);
  host.set_selection(EdgeId(0));
  ASSERT_TRUE(runner.deliver(LessonEvent::selection(EdgeId(0))));
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Condition);
  const HalfedgeMesh shown = *host.current_mesh();
  // A split is not a flip: the step keeps waiting.
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(0)).ok()); });
  runner.update(0.0);
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting);
  // Undo it (the diamond the step showed), then flip.
  host.set_current_mesh(std::make_shared<HalfedgeMesh>(shown));
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(flip(m, EdgeId(0)).ok()); });
  runner.update(0.0);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  EXPECT_TRUE(contains(said(runner), "e now runs from **d** to **c**")) << said(runner);
  // The next step highlights exactly the elements whose fields changed, then asks how many flips go round.
  runner.next();
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  for (ElementRef changed :
       {ElementRef(HalfedgeId(0)), ElementRef(HalfedgeId(1)), ElementRef(HalfedgeId(2)), ElementRef(HalfedgeId(3)),
        ElementRef(HalfedgeId(4)), ElementRef(HalfedgeId(5)), ElementRef(VertexId(0)), ElementRef(VertexId(1)),
        ElementRef(FaceId(0)), ElementRef(FaceId(1))}) {
    EXPECT_EQ(colour_of(host, changed), colour_hex(kDarkSwatches.orange)) << format_id(changed);
  }
  EXPECT_EQ(host.highlights().size(), 10u);
}

// ---- part 5: edge split ----------------------------------------------------------------------------

TEST(LessonsB, EdgeSplitPassesHeadlessNamingTheNewElements) {
  const std::string text = run_headless("5_edge_split", 7);
  // The last step runs the student's split on the middle edge of a grid of 11200 triangles too: the solution is right.
  EXPECT_TRUE(contains(text, "Last, the middle edge of a grid of 11200 triangles")) << text;
  EXPECT_TRUE(contains(text, "as the Exercises tab and the grader do.\n  > your turn split.lua: right\n")) << text;
  EXPECT_TRUE(contains(text, "The new vertex m is v4 at (0, 0, 0), the midpoint of a and b. It has 4 neighbours"))
      << text;
  EXPECT_TRUE(contains(text,
                       "edges ea = e5, ec = e6, ed = e7; faces g0 = f2 and g1 = f3; halfedges n0 to n5 = h10 "
                       "to h15. The mesh now has 5 vertices, 8 edges, 4 faces"))
      << text;
  EXPECT_TRUE(contains(text, "now runs from v4 (m) to v1 (b).")) << text;
  // The grid: e0 is the bottom row's first boundary edge; m = v9 at its midpoint, on the boundary.
  EXPECT_TRUE(
      contains(text, "This grid has 9 vertices, 16 edges, 8 faces. Click the yellow edge on its bottom row (e0)"))
      << text;
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(2, 2));
  ASSERT_TRUE(grid.is_boundary(EdgeId(0)));
  const OpResult<VertexId> m = split(grid, EdgeId(0));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.value, VertexId(9));
  EXPECT_TRUE(contains(text, "m = v9 sits on the boundary at (0.5, 0, 0) with " + std::to_string(grid.degree(m.value)) +
                                 " neighbours. The mesh has 10 vertices, "
                                 "18 edges, 9 faces"))
      << text;
  EXPECT_TRUE(contains(text, "m's halfedge is " + format_id(grid.halfedge(m.value)) + ", which lies on the boundary"))
      << text;
}

TEST(LessonsB, EdgeSplitLabelsTheNewElementsOnTheScreenMesh) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("5_edge_split")));
  runner.go_to(step_index(runner, "Split the middle edge"));
  host.set_selection(EdgeId(0));
  ASSERT_TRUE(runner.deliver(LessonEvent::selection(EdgeId(0))));
  runner.update(0.0);
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "selecting is not splitting";
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(0)).ok()); });
  runner.update(0.0);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  EXPECT_EQ(label_of(host, VertexId(4)), "m");
  EXPECT_EQ(label_of(host, EdgeId(5)), "ea");
  EXPECT_EQ(label_of(host, EdgeId(6)), "ec");
  EXPECT_EQ(label_of(host, EdgeId(7)), "ed");
  EXPECT_EQ(label_of(host, FaceId(2)), "g0");
  EXPECT_EQ(label_of(host, FaceId(3)), "g1");
  EXPECT_EQ(colour_of(host, VertexId(4)), colour_hex(kDarkSwatches.yellow));
  EXPECT_EQ(colour_of(host, EdgeId(6)), colour_hex(kDarkSwatches.orange));
  // The core's documented ids: ec = e6 joins m and c (v2), ed = e7 joins m and d (v3).
  const HalfedgeMesh* screen = host.screen_mesh();
  ASSERT_TRUE(screen);
  EXPECT_EQ(screen->vertex(screen->halfedge(EdgeId(6))), VertexId(4));
  EXPECT_EQ(screen->vertex(screen->twin(screen->halfedge(EdgeId(6)))), VertexId(2));
  EXPECT_EQ(screen->vertex(screen->twin(screen->halfedge(EdgeId(7)))), VertexId(3));
}

// ---- part 6: Loop subdivision ----------------------------------------------------------------------

TEST(LessonsB, LoopSubdivisionPassesHeadlessWithTheCoresCounts) {
  const std::string text = run_headless("6_loop_subdivision", 12);
  EXPECT_TRUE(contains(text,
                       "The yellow vertex v0 has 6 neighbours, so u = 0.0625: it will go from (-0.5, -0.5, "
                       "-0.5) to (-0.3125, -0.3125, -0.3125)."))
      << text;
  EXPECT_TRUE(contains(text,
                       "Every one of the 18 original edges has been split with the same split as part 5. The "
                       "mesh now has 26 vertices, 72 edges, 48 faces"))
      << text;
  EXPECT_TRUE(contains(text, "Of the 36 edges the splits made across faces, 12 joined an old vertex to a new one"))
      << text;
  EXPECT_TRUE(contains(text, "give exactly the mesh the app's L gives")) << text;
  EXPECT_TRUE(contains(text,
                       "  > loop phase 1/4: compute new positions\n  > key shift+L\n\n  Phase 1 computed every new "
                       "position and changed nothing: the cube still has 8 vertices, 18 edges, 12 faces."))
      << text;
  EXPECT_TRUE(contains(text, "Phase 2 split all 18 original edges: now 26 vertices, 72 edges, 48 faces")) << text;
  EXPECT_TRUE(contains(text,
                       "Phase 3 flipped the 12 new edges joining an old and a new vertex (orange): still 26 "
                       "vertices, 72 edges, 48 faces."))
      << text;
  EXPECT_TRUE(contains(text,
                       "Phase 4 moved every vertex: v0 went from (-0.5, -0.5, -0.5) to (-0.3125, -0.3125, "
                       "-0.3125)."))
      << text;
  EXPECT_TRUE(contains(text, "One step done: 26 vertices, 72 edges, 48 faces, valid.")) << text;
  EXPECT_TRUE(contains(text, "the degrees of v0 to v7 are 6, 4, 4, 4, 4, 4, 4, 6.")) << text;
  EXPECT_TRUE(contains(text, "All six split: 14 vertices, 36 edges, 24 faces, and every corner has degree 6.")) << text;
  EXPECT_TRUE(contains(text,
                       "After two steps: 194 vertices, 576 edges, 384 faces. All 8 corners are 0.5954 from the "
                       "centre"))
      << text;
  EXPECT_TRUE(contains(text,
                       "Now 25 vertices, 56 edges, 32 faces, still 1 boundary loop. The corner moved from (0, 0, "
                       "0) to (0.125, 0.125, 0)"))
      << text;

  // The asymmetry numbers are the core's: corners of the plain cube after two steps.
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  ASSERT_TRUE(loop_subdivide(cube).ok);
  ASSERT_TRUE(loop_subdivide(cube).ok);
  double lo = 1e9, hi = 0;
  for (uint32_t i = 0; i < 8; ++i) {
    const double r = glm::length(cube.position(VertexId(i)));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  char range[96];
  std::snprintf(range, sizeof range, "the 8 corners are between %.4f and %.4f from the centre", lo, hi);
  EXPECT_TRUE(contains(text, range)) << range << "\n" << text;
  EXPECT_GT(hi - lo, 0.05);
}

TEST(LessonsB, LoopPhasesShowTheCoresIntermediateMeshes) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("6_loop_subdivision")));
  // The core's phases on the same cube.
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  OpResult<LoopState> state = loop_compute_positions(cube);
  ASSERT_TRUE(state.ok());
  loop_split_edges(cube, state.value);

  runner.go_to(step_index(runner, "Phase 2: split every edge"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "it asks which edges to split first";
  ASSERT_TRUE(runner.deliver(LessonEvent::choice("The 18 original edges")));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  const HalfedgeMesh* screen = host.screen_mesh();
  ASSERT_TRUE(screen);
  ASSERT_EQ(screen->vertex_capacity(), cube.vertex_capacity());
  for (uint32_t i = 0; i < cube.vertex_capacity(); ++i) {
    EXPECT_EQ(screen->position(VertexId(i)), cube.position(VertexId(i))) << i;
    EXPECT_EQ(colour_of(host, VertexId(i)), i >= 8 ? colour_hex(kDarkSwatches.yellow) : std::string()) << i;
  }
  size_t cross = 0;
  for (EdgeId e : cube.edges()) {
    const bool is_cross = e.index < state.value.is_new_edge.size() && state.value.is_new_edge[e.index];
    cross += is_cross;
    EXPECT_EQ(colour_of(host, e), is_cross ? colour_hex(kDarkSwatches.orange) : "") << format_id(e);
  }
  EXPECT_EQ(cross, 36u);

  // Phase 3 asks for an edge to flip on the split cube: a half of a split original edge (e0 keeps its id as the
  // half m-b) is wrong and keeps the step waiting; e19, a new edge from a corner to a new vertex, is right.
  runner.go_to(step_index(runner, "Phase 3: which edges flip"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  EXPECT_TRUE(state.value.is_new_edge[19] && !state.value.is_new_edge[0]);
  runner.deliver(LessonEvent::click(EdgeId(0)));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  ASSERT_TRUE(runner.deliver(LessonEvent::click(EdgeId(19))));
  loop_flip_edges(cube, state.value);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  screen = host.screen_mesh();
  for (HalfedgeId h : cube.halfedges()) {
    EXPECT_EQ(screen->next(h), cube.next(h)) << format_id(h);
    EXPECT_EQ(screen->vertex(h), cube.vertex(h)) << format_id(h);
  }
  EXPECT_EQ(host.highlights().size(), 12u);

  loop_commit_positions(cube, state.value);
  runner.go_to(step_index(runner, "Phase 4: move"));
  ASSERT_TRUE(runner.deliver(LessonEvent::choice("The neighbours have changed")));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  screen = host.screen_mesh();
  for (VertexId v : cube.vertices()) {
    EXPECT_NEAR(glm::length(screen->position(v) - cube.position(v)), 0.0, 1e-12) << format_id(v);
  }
}

TEST(LessonsB, ShiftLStepChecksEveryPhaseAndStartsAgainOnAnotherEdit) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("6_loop_subdivision")));
  runner.go_to(step_index(runner, "The app's phases: Shift+L"));
  const LessonEvent shift_l = LessonEvent::key("shift+L");
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Key);
  EXPECT_EQ(runner.waiting_for().hint, "Press Shift+L: phase 1 of 4, compute new positions");
  ASSERT_TRUE(host.screen_mesh());
  // The window's Shift+L: the core's phase on the screen mesh, then the key.
  LoopState state;
  const auto phase = [&](int k) {
    edit_screen(host, [&](HalfedgeMesh& m) {
      if (k == 1) state = loop_compute_positions(m).value;
      if (k == 2) loop_split_edges(m, state);
      if (k == 3) loop_flip_edges(m, state);
      if (k == 4) loop_commit_positions(m, state);
    });
    return runner.deliver(shift_l);
  };
  ASSERT_TRUE(phase(1));
  EXPECT_TRUE(contains(said(runner), "Phase 1 computed every new position and changed nothing")) << said(runner);
  EXPECT_EQ(runner.waiting_for().hint, "Press Shift+L: phase 2 of 4, split every original edge");
  ASSERT_TRUE(phase(2));
  EXPECT_TRUE(contains(said(runner), "Phase 2 split all 18 original edges: now 26 vertices, 72 edges, 48 faces"));
  for (uint32_t i = 0; i < 26; ++i) {
    EXPECT_EQ(colour_of(host, VertexId(i)), i >= 8 ? colour_hex(kDarkSwatches.yellow) : std::string()) << i;
  }

  // L instead of phase 3 (a whole subdivision of the split cube), then Shift+L: not the cube after phase 3.
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(loop_subdivide(m).ok); });
  ASSERT_TRUE(runner.deliver(shift_l));
  EXPECT_TRUE(contains(said(runner), "That is not the cube after phase 3")) << said(runner);
  EXPECT_EQ(host.screen_mesh()->num_vertices(), 8u);  // a fresh cube, from phase 1
  EXPECT_EQ(runner.waiting_for().hint, "Press Shift+L: phase 1 of 4, compute new positions");
  EXPECT_TRUE(host.highlights().empty());

  for (int k = 1; k <= 4; ++k) ASSERT_TRUE(phase(k)) << k;
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  EXPECT_TRUE(contains(said(runner), "Phase 3 flipped the 12 new edges")) << said(runner);
  EXPECT_TRUE(contains(said(runner),
                       "Phase 4 moved every vertex: v0 went from (-0.5, -0.5, -0.5) to (-0.3125, "
                       "-0.3125, -0.3125)."))
      << said(runner);
  EXPECT_TRUE(contains(said(runner), "One step done: 26 vertices, 72 edges, 48 faces, valid.")) << said(runner);
  EXPECT_EQ(colour_of(host, VertexId(0)), colour_hex(kDarkSwatches.yellow));
}

TEST(LessonsB, PreSplitWaitsForAllSixDiagonals) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("6_loop_subdivision")));
  runner.go_to(step_index(runner, "The pre-split fix"));
  const uint32_t diagonals[] = {2, 7, 11, 14, 16, 17};
  for (uint32_t e : diagonals) EXPECT_EQ(colour_of(host, EdgeId(e)), colour_hex(kDarkSwatches.yellow)) << e;
  EXPECT_EQ(host.highlights().size(), 6u);
  for (size_t i = 0; i < 5; ++i) {
    edit_screen(host, [&](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(diagonals[i])).ok()); });
    runner.update(0.0);
    EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << i;
  }
  // The sixth split meets the first check; the second waits for two steps of L.
  edit_screen(host, [&](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(diagonals[5])).ok()); });
  runner.update(0.0);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting);
  EXPECT_TRUE(contains(said(runner), "All six split: 14 vertices, 36 edges, 24 faces")) << said(runner);
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(loop_subdivide(m).ok); });
  runner.update(0.0);
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "one L of two";
  edit_screen(host, [](HalfedgeMesh& m) { ASSERT_TRUE(loop_subdivide(m).ok); });
  runner.update(0.0);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  EXPECT_TRUE(contains(said(runner), "All 8 corners are 0.5954 from the centre")) << said(runner);
}

// ---- part 7: Catmull-Clark subdivision -------------------------------------------------------------

// A number as lesson 7 prints it: at most four decimals, trailing zeros dropped, never "-0".
std::string lesson_number(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4f", x + 0.0);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string lesson_point(const glm::dvec3& p) {
  return "(" + lesson_number(p.x) + ", " + lesson_number(p.y) + ", " + lesson_number(p.z) + ")";
}

std::string lesson_counts(const HalfedgeMesh& mesh) {
  return std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(mesh.num_edges()) + " edges, " +
         std::to_string(mesh.num_faces()) + " faces";
}

// The lesson's grid of n by n unit quads in the z = 0 plane, row by row from v0 at (0, 0).
HalfedgeMesh quad_grid(uint32_t n) {
  PolygonMesh polygons;
  for (uint32_t y = 0; y <= n; ++y) {
    for (uint32_t x = 0; x <= n; ++x) polygons.add_vertex({double(x), double(y), 0});
  }
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      const uint32_t a = y * (n + 1) + x;
      polygons.add_face({a, a + 1, a + n + 2, a + n + 1});
    }
  }
  return build_halfedge_mesh(polygons);
}

EdgeId edge_between(const HalfedgeMesh& mesh, VertexId a, VertexId b) {
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const VertexId u = mesh.vertex(h), w = mesh.vertex(mesh.twin(h));
    if ((u == a && w == b) || (u == b && w == a)) return e;
  }
  ADD_FAILURE() << "no edge between " << format_id(a) << " and " << format_id(b);
  return EdgeId(0);
}

// Each face, edge and vertex point the lesson prints is the one the core's phase 1 computes (the lesson reads them
// back from mesh:catmull_clark() by the documented id layout), and every count, the linear mesh and the three
// levels are the core's too.
TEST(LessonsB, CatmullClarkPassesHeadlessWithTheCoresPoints) {
  const std::string text = run_headless("7_catmull_clark", 9);
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube_quads());
  const OpResult<CatmullClarkState> state = catmull_clark_compute_points(cube);
  ASSERT_TRUE(state.ok());

  // Face points: f1 is the top, z = 0.5.
  const HalfedgeId top = cube.halfedge(FaceId(1));
  HalfedgeId h = top;
  do {
    EXPECT_EQ(cube.position(cube.vertex(h)).z, 0.5);
    h = cube.next(h);
  } while (h != top);
  EXPECT_TRUE(
      contains(text, "The core puts it at " + lesson_point(state.value.face_point[1]) + ": the centre of the top."))
      << text;

  // Edge points: the edge from v0 to v1, pulled in from its midpoint.
  const EdgeId e = edge_between(cube, VertexId(0), VertexId(1));
  const glm::dvec3 midpoint = 0.5 * (cube.position(VertexId(0)) + cube.position(VertexId(1)));
  const glm::dvec3 edge_point = state.value.edge_point[e.index];
  EXPECT_GT(glm::length(edge_point - midpoint), 0.1);
  EXPECT_TRUE(contains(text, "The orange edge " + format_id(e) + " runs from")) << text;
  EXPECT_TRUE(contains(text, "The core puts it at " + lesson_point(edge_point) +
                                 ". The blue arrow goes from the "
                                 "midpoint " +
                                 lesson_point(midpoint) + " to it: the two face points pull it " +
                                 lesson_number(glm::length(midpoint - edge_point)) + " in"))
      << text;

  // Vertex points: the corner v0 keeps 5/9 of its distance from the centre.
  const glm::dvec3 corner = state.value.vertex_point[0];
  EXPECT_NEAR(glm::length(corner) / glm::length(cube.position(VertexId(0))), 5.0 / 9.0, 1e-12);
  EXPECT_TRUE(contains(text, "The core moves v0 to " + lesson_point(corner) +
                                 " (blue arrow): 5/9 of its distance "
                                 "from the centre"))
      << text;

  // Counts after one level, on the cube and on the tetrahedron.
  HalfedgeMesh once = cube;
  ASSERT_TRUE(catmull_clark_subdivide(once).ok);
  EXPECT_EQ(once.num_vertices(), cube.num_vertices() + cube.num_edges() + cube.num_faces());
  // The student's Subdivide > Catmull-Clark on the cube on screen (the answers' {subdivide = "catmull-clark"}).
  EXPECT_TRUE(contains(text, "  > subdivide catmull-clark\n")) << text;
  EXPECT_TRUE(
      contains(text, "Your level: " + lesson_counts(once) + ", all " + std::to_string(once.num_faces()) + " quads."))
      << text;
  EXPECT_TRUE(contains(text, "so the 24 corners of the old faces give " + std::to_string(once.num_faces()) +
                                 " quads and E' = 2E + 24 = " + std::to_string(once.num_edges()) + " edges."))
      << text;
  // The app's phases (the answers' {subdivide_phase = "catmull-clark"}, three times): what each phase left, as the
  // core's phases leave it.
  HalfedgeMesh stepped = cube;
  catmull_clark_refine(stepped, state.value);
  const VertexId new_vertex(uint32_t(cube.num_vertices() + e.index));
  EXPECT_EQ(stepped.position(new_vertex), midpoint);
  EXPECT_TRUE(contains(text, "  > catmull-clark phase 1/3: compute face, edge and vertex points\n")) << text;
  EXPECT_TRUE(contains(text,
                       "Phase 1 computed 6 face points, 12 edge points and 8 vertex points, and nothing "
                       "moved: the edge point of " +
                           format_id(e) + " is " + lesson_point(edge_point) + ", the vertex point of v0 " +
                           lesson_point(corner) + "."))
      << text;
  EXPECT_TRUE(contains(text, "Phase 2 split the 6 faces into 24 quads. The new vertex " + format_id(new_vertex) +
                                 " sits at " + lesson_point(midpoint) + ", the midpoint"))
      << text;
  catmull_clark_commit_positions(stepped, state.value);
  EXPECT_TRUE(stepped.same_as(once));
  EXPECT_TRUE(contains(text, "Phase 3 moved every vertex to its point: " + format_id(new_vertex) + " to " +
                                 lesson_point(stepped.position(new_vertex)) + ", the edge point, and v0 to " +
                                 lesson_point(stepped.position(VertexId(0))) +
                                 ", its vertex point. One level done: " + lesson_counts(stepped) + "."))
      << text;
  HalfedgeMesh tetrahedron = build_halfedge_mesh(make_tetrahedron());
  ASSERT_TRUE(catmull_clark_subdivide(tetrahedron).ok);
  for (FaceId f : tetrahedron.faces()) EXPECT_EQ(tetrahedron.degree(f), 4u) << format_id(f);
  EXPECT_TRUE(contains(text, "The core's level: " + lesson_counts(tetrahedron) + ", all " +
                                 std::to_string(tetrahedron.num_faces()) + " quads. After one level"))
      << text;

  // The boundary: a boundary edge's point is its midpoint, the grid's corner goes to 3/4 P + 1/8 (r0 + r1).
  const HalfedgeMesh grid = quad_grid(2);
  const OpResult<CatmullClarkState> grid_state = catmull_clark_compute_points(grid);
  ASSERT_TRUE(grid_state.ok());
  const EdgeId boundary = edge_between(grid, VertexId(0), VertexId(1));
  EXPECT_EQ(grid_state.value.edge_point[boundary.index], glm::dvec3(0.5, 0, 0));
  EXPECT_TRUE(contains(
      text, "The core puts it at the midpoint, " + lesson_point(grid_state.value.edge_point[boundary.index]) + "."))
      << text;
  HalfedgeMesh grid_once = grid;
  ASSERT_TRUE(catmull_clark_subdivide(grid_once).ok);
  EXPECT_TRUE(contains(text, "The core's level: " + lesson_counts(grid_once) + ", still " +
                                 std::to_string(grid_once.num_boundaries()) +
                                 " boundary loop. The corner went from "
                                 "(0, 0, 0) to " +
                                 lesson_point(grid_state.value.vertex_point[0])))
      << text;
  EXPECT_EQ(grid_state.value.vertex_point[0], glm::dvec3(0.125, 0.125, 0));

  // Linear subdivision moves no old vertex; Catmull-Clark moves v0; three levels.
  HalfedgeMesh linear = cube;
  ASSERT_TRUE(linear_subdivide(linear).ok);
  for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(linear.position(VertexId(i)), cube.position(VertexId(i))) << i;
  EXPECT_TRUE(contains(text, "Left, linear: not one old vertex moved, and v0 is still at " +
                                 lesson_point(linear.position(VertexId(0))) + ". Right, Catmull-Clark: v0 went to " +
                                 lesson_point(once.position(VertexId(0))) + ". Both have " + lesson_counts(linear)))
      << text;
  HalfedgeMesh thrice = cube;
  ASSERT_TRUE(catmull_clark_subdivide(thrice, 3).ok);
  EXPECT_TRUE(contains(text, "after three levels it is " + lesson_number(glm::length(thrice.position(VertexId(0)))) +
                                 " from it, and there are " + std::to_string(thrice.num_faces()) + " quads"))
      << text;
}

// Driven step by step: a wrong vertex point keeps the step waiting; the right one draws the arrow from the corner to
// the core's vertex point. The last step shows the linear and the Catmull-Clark cube side by side, v0 of each
// labelled.
TEST(LessonsB, CatmullClarkVertexPointArrowIsTheCoresAndTheLastStepShowsBoth) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("7_catmull_clark"))) << runner.error();
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube_quads());
  const OpResult<CatmullClarkState> state = catmull_clark_compute_points(cube);
  ASSERT_TRUE(state.ok());

  runner.go_to(step_index(runner, "Vertex points"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  EXPECT_EQ(label_of(host, VertexId(0)), "v0, n = 3");
  EXPECT_EQ(colour_of(host, VertexId(0)), colour_hex(kDarkSwatches.yellow));
  ASSERT_TRUE(runner.deliver(LessonEvent::choice("Towards the centre, along the diagonal")));  // asked first
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  runner.deliver(LessonEvent::value("-0.5, -0.5, -0.5"));  // the corner where it was
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "a wrong answer keeps the step waiting";
  EXPECT_TRUE(host.arrows().empty());
  const glm::dvec3 p = state.value.vertex_point[0];
  char typed[128];
  std::snprintf(typed, sizeof typed, "%.17g, %.17g, %.17g", p.x, p.y, p.z);
  ASSERT_TRUE(runner.deliver(LessonEvent::value(typed)));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  ASSERT_EQ(host.arrows().size(), 1u);
  EXPECT_EQ(host.arrows()[0].from, cube.position(VertexId(0)));
  EXPECT_EQ(host.arrows()[0].to, p);

  runner.go_to(step_index(runner, "Linear subdivision beside it"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  ASSERT_TRUE(runner.deliver(LessonEvent::choice("Where it was")));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  HalfedgeMesh once = cube;
  ASSERT_TRUE(catmull_clark_subdivide(once).ok);
  const HalfedgeMesh* screen = host.screen_mesh();
  ASSERT_TRUE(screen);
  const uint32_t right = static_cast<uint32_t>(once.num_vertices());
  EXPECT_EQ(screen->num_vertices(), 2 * once.num_vertices());
  EXPECT_EQ(screen->num_faces(), 2 * once.num_faces());
  EXPECT_EQ(screen->position(VertexId(0)), cube.position(VertexId(0)));
  // The right-hand copy is the core's level moved along x.
  const glm::dvec3 offset = screen->position(VertexId(right)) - once.position(VertexId(0));
  EXPECT_GT(offset.x, 1.0);
  EXPECT_EQ(offset.y, 0.0);
  EXPECT_EQ(offset.z, 0.0);
  EXPECT_EQ(label_of(host, VertexId(0)), "linear");
  EXPECT_EQ(label_of(host, VertexId(right)), "Catmull-Clark");
}

// ---- bring your own mesh ---------------------------------------------------------------------------

// The lesson's three broken pieces (lessons/byo_mesh.lua: BOWTIE, FIN, FLIPPED), as polygons with 0-based corners.
PolygonMesh bowtie() {
  PolygonMesh polygons;
  polygons.positions = {{0, 0, 0}, {1, 0.5, 0}, {1, -0.5, 0}, {-1, -0.5, 0}, {-1, 0.5, 0}};
  polygons.add_face({0, 1, 2});
  polygons.add_face({0, 3, 4});
  return polygons;
}
PolygonMesh fin() {
  PolygonMesh polygons;
  polygons.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  polygons.add_face({0, 1, 2});
  polygons.add_face({1, 0, 3});
  polygons.add_face({0, 1, 4});
  return polygons;
}
PolygonMesh flipped() {
  PolygonMesh polygons;
  polygons.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
  polygons.add_face({0, 1, 2});
  polygons.add_face({0, 1, 3});
  return polygons;
}
// The three side by side, 3 apart along x, as the lesson's "Repairs tab" step puts them in one list.
PolygonMesh all_three() {
  PolygonMesh all;
  double shift = 0;
  for (const PolygonMesh& piece : {bowtie(), fin(), flipped()}) {
    const uint32_t base = static_cast<uint32_t>(all.positions.size());
    for (const glm::dvec3& p : piece.positions) all.positions.push_back(p + glm::dvec3(shift, 0, 0));
    for (size_t f = 0; f < piece.num_faces(); ++f) {
      std::vector<uint32_t> corners;
      for (uint32_t corner : piece.face(f)) corners.push_back(base + corner);
      all.add_face(corners);
    }
    shift += 3;
  }
  return all;
}

// The refusal the core gives the polygons (the lesson prints it after "from_polygons: ").
std::string refusal_of(const PolygonMesh& polygons) {
  try {
    build_halfedge_mesh(polygons);
  } catch (const MeshError& error) {
    return error.what();
  }
  ADD_FAILURE() << "the polygons were accepted";
  return "";
}

// The repair's summary and each change line, as the lesson lists them, are in the transcript, with the counts.
void expect_report(const std::string& text, const PolygonMesh& polygons) {
  const RepairResult repaired = repair_polygons(polygons);
  ASSERT_FALSE(repaired.report.empty());
  EXPECT_TRUE(contains(text, "\n  " + repaired.report.summary() + "\n")) << text;
  for (const std::string& change : repaired.report.changes) EXPECT_TRUE(contains(text, "- " + change)) << text;
  EXPECT_TRUE(contains(text, lesson_counts(build_halfedge_mesh(repaired.polygons)) + ".")) << text;
}

// Every step passes with each question answered wrong once (its feedback naming the mistake) and then right; the
// right answers, the refusals, the repair reports and the counts are the core's own.
TEST(LessonsB, BringYourOwnMeshPassesHeadlessWithTheCoresReports) {
  const std::string text = run_headless("byo_mesh", 7);

  // The shipped scan: the student opens a repaired copy; the counts and every report line are the core's.
  const RepairResult scan = repair_polygons(load_mesh(testing::source_dir() / "assets" / "scan_with_defects.ply"));
  const HalfedgeMesh scan_mesh = build_halfedge_mesh(scan.polygons);
  EXPECT_TRUE(contains(text, "> answer " + std::to_string(scan_mesh.num_faces()) + ": right")) << text;
  EXPECT_TRUE(contains(text, "  > open a repaired copy of ../assets/scan_with_defects.ply\n")) << text;
  EXPECT_TRUE(contains(text, "The repaired copy: " + lesson_counts(scan_mesh) + ".")) << text;
  EXPECT_TRUE(contains(text, scan.report.summary())) << text;
  ASSERT_EQ(scan.report.changes.size(), 3u);
  for (const std::string& change : scan.report.changes) EXPECT_TRUE(contains(text, "- " + change)) << change;

  // Up axis: a scan (.ply) and a glTF are shown with the axis the window's rule gives them; Z up is the override.
  const auto ply = format_up_axis("bunny.ply");
  ASSERT_TRUE(ply);
  EXPECT_TRUE(contains(text, "> choose " + std::string(up_axis_name(*ply)) + ": right")) << text;
  const auto glb = format_up_axis("chair.glb");
  ASSERT_TRUE(glb);
  EXPECT_EQ(*glb, UpAxis::Y) << "the lesson says a .glb opens Y-up, so a Z-up export lies on its side";
  EXPECT_TRUE(contains(text, "> choose View > Up axis > " + std::string(up_axis_name(UpAxis::Z)) + ": right")) << text;

  // The bow-tie: the answer is the repaired vertex count; the refusal and the report are the core's.
  const PolygonMesh tie = bowtie();
  const RepairResult tie_fixed = repair_polygons(tie);
  EXPECT_TRUE(contains(text, "> answer " + std::to_string(tie_fixed.polygons.positions.size()) + ": right")) << text;
  EXPECT_NE(tie_fixed.polygons.positions.size(), tie.positions.size());
  EXPECT_TRUE(contains(text, "Refused as it is: from_polygons: " + refusal_of(tie).substr(0, 40))) << text;
  expect_report(text, tie);

  // The fin and the flipped face: the faces chosen are the ones the report names.
  const RepairResult fin_fixed = repair_polygons(fin());
  ASSERT_EQ(fin_fixed.report.detached_faces, 1u);
  ASSERT_EQ(fin_fixed.report.spots.size(), 1u);
  ASSERT_EQ(fin_fixed.report.spots[0].faces.size(), 1u);
  EXPECT_TRUE(contains(text, "> choose face " + std::to_string(fin_fixed.report.spots[0].faces[0]) + ": right"))
      << text;
  expect_report(text, fin());
  const RepairResult flip_fixed = repair_polygons(flipped());
  ASSERT_EQ(flip_fixed.report.reversed_faces, 1u);
  EXPECT_TRUE(contains(text, "> choose face " + std::to_string(flip_fixed.report.spots[0].faces[0]) + ": right"))
      << text;
  expect_report(text, flipped());
  EXPECT_TRUE(contains(text, "Refused: from_polygons: " + refusal_of(fin()).substr(0, 40))) << text;
  EXPECT_TRUE(contains(text, "Refused: from_polygons: " + refusal_of(flipped()).substr(0, 40))) << text;

  // The Repairs tab: the whole list, and the face clicked is the spot of the "reversed" change.
  const RepairResult all_fixed = repair_polygons(all_three());
  expect_report(text, all_three());
  for (size_t i = 0; i < all_fixed.report.changes.size(); ++i) {
    if (!contains(all_fixed.report.changes[i], "reversed")) continue;
    ASSERT_EQ(all_fixed.report.spots[i].faces.size(), 1u);
    EXPECT_TRUE(contains(text, "> click f" + std::to_string(all_fixed.report.spots[i].faces[0]) + ": right")) << text;
  }

  // Triangulate: Loop's refusal of Suzanne's quads (the Blender export the app ships), and the counts before and after.
  HalfedgeMesh quads = build_halfedge_mesh(load_mesh(testing::source_dir() / "assets" / "suzanne.obj"));
  HalfedgeMesh refused = quads;
  const Check loop_quads = loop_subdivide(refused);
  ASSERT_FALSE(loop_quads.ok);
  EXPECT_TRUE(contains(text, "the status bar says why: " + loop_quads.reason + ".")) << text;
  HalfedgeMesh triangles = quads;
  const OpResult<TriangulationReport> split = triangulate_mesh(triangles);
  ASSERT_TRUE(split.ok());
  EXPECT_TRUE(contains(text, "> answer " + std::to_string(triangles.num_faces()) + ": right")) << text;
  // The student's Edit > Triangulate on the mesh on screen (the answers' {triangulate = true}).
  EXPECT_TRUE(contains(text, "  > triangulate\n")) << text;
  EXPECT_TRUE(contains(text, "Triangulate split " + std::to_string(split.value.polygons_split) + " faces: " +
                                 lesson_counts(quads) + " before, " + lesson_counts(triangles) + " after."))
      << text;

  // Subdivide: L on the triangulated Suzanne, then Catmull-Clark's and Linear's counts.
  HalfedgeMesh loop = triangles;
  ASSERT_TRUE(loop_subdivide(loop).ok);
  EXPECT_TRUE(contains(text, "Loop: " + lesson_counts(loop) + ".")) << text;
  HalfedgeMesh cc = triangles;
  ASSERT_TRUE(catmull_clark_subdivide(cc).ok);
  EXPECT_TRUE(contains(text, "> answer " + std::to_string(cc.num_faces()) + ": right")) << text;
  EXPECT_TRUE(contains(text, "Catmull-Clark: " + lesson_counts(cc) + ", all quads.")) << text;
  HalfedgeMesh linear = triangles;
  ASSERT_TRUE(linear_subdivide(linear).ok);
  EXPECT_TRUE(contains(text, "(" + lesson_counts(linear) + ") but moves no vertex")) << text;
}

// The last step reads the student's mesh: a triangle mesh is subdivided where it is; a quad mesh is sent back.
TEST(LessonsB, BringYourOwnMeshSubdividesTheStudentsMesh) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("byo_mesh")));
  const HalfedgeMesh ico = build_halfedge_mesh(make_icosahedron());
  host.set_current_mesh(std::make_shared<HalfedgeMesh>(ico));
  runner.go_to(step_index(runner, "Subdivide it"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << runner.error();
  EXPECT_TRUE(contains(said(runner), "(" + lesson_counts(ico) + ")")) << said(runner);
  runner.update(0.1);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "it waits until the mesh is subdivided";
  EXPECT_FALSE(contains(said(runner), "Loop: ")) << said(runner);
  edit_screen(host, [](HalfedgeMesh& mesh) { ASSERT_TRUE(loop_subdivide(mesh).ok); });
  runner.update(0.1);
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Waiting) << "then asks about Catmull-Clark" << runner.error();
  HalfedgeMesh loop = ico;
  ASSERT_TRUE(loop_subdivide(loop).ok);
  EXPECT_TRUE(contains(said(runner), "Loop: " + lesson_counts(loop) + ".")) << said(runner);

  host.set_current_mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube_quads())));
  runner.go_to(step_index(runner, "Subdivide it"));
  ASSERT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
  EXPECT_TRUE(contains(said(runner), "Go Back to triangulate it.")) << said(runner);
}

}  // namespace
}  // namespace meshedit
