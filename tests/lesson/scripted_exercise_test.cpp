// Exercises defined in Lua alone (scripted_exercise.h), on the shipped scripts/exercises/collapse.lua: its fields and
// fixtures; the catalogue (an id past the built-ins, kept when registered again); check_exercise with the correct
// solution (right on every fixture, with the mesh the core's collapse makes), a buggy one (the definition's diagnosis
// first), a refused edge, the hidden reference; a lesson's your_turn asking for it; and a broken definition named at
// its file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::path definition_path() { return testing::source_dir() / "scripts" / "exercises" / "collapse.lua"; }
fs::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }
fs::path buggy() { return testing::source_dir() / "tests" / "grading" / "scripted" / "collapse_keeps_position.lua"; }

Exercise collapse_exercise() {
  static const Exercise id = register_scripted_exercise(ScriptedExercise::load(definition_path()));
  return id;
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// The message ScriptedExercise::load throws for a definition file holding `text`.
std::string load_error(const std::string& text) {
  const fs::path file = write(testing::scratch_dir(), "bad.lua", text);
  try {
    ScriptedExercise::load(file);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "(it loaded)";
}

TEST(ScriptedExercise, TheShippedCollapseDefinitionLoadsWithItsFixtures) {
  const auto definition = ScriptedExercise::load(definition_path());
  EXPECT_STREQ(definition->info().name, "collapse");
  EXPECT_STREQ(definition->info().file, "collapse.lua");
  EXPECT_STREQ(definition->info().function, "collapse_edge");
  EXPECT_STREQ(definition->info().signature, "collapse_edge(mesh, e) -> the vertex that remains, or nil");
  ASSERT_TRUE(definition->takes().has_value());
  EXPECT_EQ(*definition->takes(), ElementKind::Edge);
  EXPECT_TRUE(definition->api().allow_api.empty());
  ASSERT_EQ(definition->fixtures().size(), 3u);
  const ScriptedFixture& grid = definition->fixtures()[2];
  EXPECT_EQ(grid.name, "a diagonal of a 2x2 grid's corner square");
  EXPECT_EQ(grid.points, 1.0);
  EXPECT_EQ(grid.element, ElementRef(EdgeId(2)));
  const HalfedgeId h = grid.mesh->halfedge(EdgeId(2));
  EXPECT_EQ(grid.mesh->position(grid.mesh->vertex(h)), glm::dvec3(1, 1, 0));
  EXPECT_EQ(grid.mesh->position(grid.mesh->vertex(grid.mesh->twin(h))), glm::dvec3(0, 0, 0));
  EXPECT_EQ(definition->fixtures()[0].mesh->num_vertices(), 12u);
}

TEST(ScriptedExercise, ARegisteredExerciseIsAnExerciseLikeTheBuiltInOnes) {
  const Exercise id = collapse_exercise();
  EXPECT_EQ(id.kind(), ExerciseKind::Scripted);
  EXPECT_EQ(id.definition()->info().name, std::string("collapse"));
  EXPECT_EQ(find_exercise("collapse"), id);
  EXPECT_EQ(find_exercise("collapse_edge"), id);
  EXPECT_EQ(find_exercise("flip"), Exercise::FlipEdge);  // the built-ins first
  EXPECT_STREQ(exercise_info(id).file, "collapse.lua");
  EXPECT_TRUE(is_mesh_exercise(id));
  EXPECT_EQ(register_scripted_exercise(ScriptedExercise::load(definition_path())), id);  // again: the same id
  const std::vector<Exercise> scripted = exercise_registry().scripted();
  EXPECT_NE(std::find(scripted.begin(), scripted.end(), id), scripted.end());
  const auto mesh = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_icosahedron()));
  EXPECT_EQ(ExerciseInput::element_of(mesh, EdgeId(3)).describe(id), "e3 of a mesh with 12 vertices and 20 faces");
}

TEST(ScriptedExercise, TheCorrectSolutionGivesTheCoresCollapseOnEveryFixture) {
  const Exercise id = collapse_exercise();
  auto code = load_student_file(solutions() / "collapse.lua");
  for (const ScriptedFixture& fixture : id.definition()->fixtures()) {
    const ExerciseReport report =
        check_exercise(*code, id, ExerciseInput::element_of(fixture.mesh, fixture.element), RunOptions{true});
    EXPECT_TRUE(report.equal) << fixture.name << ": " << report.summary();
    ASSERT_TRUE(report.mine.mesh);
    HalfedgeMesh core = *fixture.mesh;
    const OpResult<VertexId> kept = collapse(core, EdgeId(fixture.element.index));
    ASSERT_TRUE(kept.ok());
    const HalfedgeMesh& mine = *report.mine.mesh;
    EXPECT_EQ(mine.num_vertices(), fixture.mesh->num_vertices() - 1) << fixture.name;
    EXPECT_EQ(mine.num_faces(), fixture.mesh->num_faces() - 2) << fixture.name;
    EXPECT_EQ(mine.num_edges(), fixture.mesh->num_edges() - 3) << fixture.name;
    ASSERT_EQ(report.mine.element.kind, ElementKind::Vertex);
    EXPECT_TRUE(testing::near(mine.position(VertexId(report.mine.element.index)), core.position(kept.value), 1e-12));
    EXPECT_TRUE(mine.alive(report.mine.element));
    EXPECT_FALSE(report.mine.edits.empty()) << "the replay has the writes";
  }
}

TEST(ScriptedExercise, TheDefinitionsDiagnosisComesFirst) {
  const Exercise id = collapse_exercise();
  auto code = load_student_file(buggy(), {});
  const ScriptedFixture& fixture = id.definition()->fixtures()[2];
  const ExerciseReport report = check_exercise(*code, id, ExerciseInput::element_of(fixture.mesh, fixture.element));
  EXPECT_FALSE(report.equal);
  ASSERT_GE(report.differences.size(), 2u);
  EXPECT_EQ(report.differences[0],
            "the vertex that remains is still where a was; collapse moves it to the midpoint "
            "of a and b, (0.5, 0.5, 0)");
  EXPECT_NE(report.differences[1].find("your vertex v4 at (1, 1, 0) has no match in the reference"), std::string::npos)
      << report.differences[1];
}

TEST(ScriptedExercise, WhereTheReferenceRefusesYoursMustChangeNothing) {
  const Exercise id = collapse_exercise();
  auto code = load_student_file(solutions() / "collapse.lua");  // it collapses without the manifold checks
  const auto grid = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_grid(2, 2)));
  const ExerciseReport report = check_exercise(*code, id, ExerciseInput::element_of(grid, EdgeId(7)));
  EXPECT_FALSE(report.equal);
  EXPECT_EQ(report.reference.returned, "nil");
  ASSERT_FALSE(report.differences.empty());
  EXPECT_NE(report.differences[0].find("the reference does not change the mesh in collapse_edge on e7 (v5 and v1 are "
                                       "both on the boundary but e7 is not"),
            std::string::npos)
      << report.differences[0];
  EXPECT_NE(report.differences[0].find("but your collapse_edge changed the mesh"), std::string::npos);
}

TEST(ScriptedExercise, TheReferenceIsHiddenFromTheStudentsCode) {
  const Exercise id = collapse_exercise();
  const fs::path dir = testing::scratch_dir();
  write(dir, "collapse.lua", "function collapse_edge(mesh, e)\n  return mesh:collapse(e)\nend\n");
  auto code = load_student_file(dir / "collapse.lua");
  const auto ico = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_icosahedron()));
  const ExerciseReport report = check_exercise(*code, id, ExerciseInput::element_of(ico, EdgeId(0)));
  EXPECT_FALSE(report.equal);
  EXPECT_NE(report.mine.error.find("collapse.lua:2: mesh:collapse is hidden from your code"), std::string::npos)
      << report.mine.error;
}

TEST(ScriptedExercise, ALessonsYourTurnAsksForItByName) {
  collapse_exercise();
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = write(dir, "lesson.lua", R"lua(lesson { title = "Collapse" }
step("Your turn", function()
  local ico = meshedit.icosahedron()
  your_turn { exercise = "collapse", mesh = ico, element = "e0" }
  say "right"
end)
)lua");
  const fs::path right = write(dir, "right.lua", "return { [1] = { {your_turn = \"right\"} } }\n");
  const fs::path wrong =
      write(dir, "wrong.lua", "return { [1] = { {your_turn = \"wrong\", feedback = \"still where a was\"} } }\n");
  std::ostringstream out;
  HeadlessOutcome outcome = run_lesson_headless(lesson, right, out, LessonRunner::default_limits(), solutions());
  EXPECT_EQ(outcome.failure, "") << out.str();
  EXPECT_NE(out.str().find("  > your turn collapse.lua: right"), std::string::npos) << out.str();

  fs::create_directories(dir / "buggy");
  fs::copy_file(buggy(), dir / "buggy" / "collapse.lua");
  std::ostringstream out2;
  outcome = run_lesson_headless(lesson, wrong, out2, LessonRunner::default_limits(), dir / "buggy");
  EXPECT_EQ(outcome.failure, "") << out2.str();
  EXPECT_NE(out2.str().find("  > your turn collapse.lua: wrong: the vertex that remains is still where a was"),
            std::string::npos)
      << out2.str();
}

// A your_turn without a hint of its own shows the definition's under a wrong answer.
TEST(ScriptedExercise, AWaitingYourTurnShowsTheDefinitionsHint) {
  const Exercise id = collapse_exercise();
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  fs::copy_file(buggy(), dir / "student" / "collapse.lua");
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  ASSERT_TRUE(runner.load(write(dir, "lesson.lua", R"lua(lesson { title = "Collapse" }
step("Your turn", function()
  your_turn { exercise = "collapse", mesh = meshedit.icosahedron(), element = "e0" }
end)
)lua")))
      << runner.error();
  const LessonWait& wait = runner.waiting_for();
  ASSERT_EQ(wait.kind, LessonWait::Kind::YourTurn) << runner.error();
  EXPECT_EQ(wait.hint, id.definition()->hint());
  EXPECT_EQ(wait.hint.rfind("Read every handle first (h0 to h5, a to d, t2 to t5)", 0), 0u) << wait.hint;
  EXPECT_EQ(wait.feedback.rfind("the vertex that remains is still where a was", 0), 0u) << wait.feedback;
}

TEST(ScriptedExercise, ABrokenDefinitionIsNamedAtItsLine) {
  const std::string head = R"lua(exercise {
  name = "minimal", file = "minimal.lua", call = "do_it",
)lua";
  const std::string reference = "  reference = function(mesh, e) return mesh:collapse(e) end,\n";
  EXPECT_EQ(load_error(head + reference + "}\n"), "bad.lua:1: exercise: takes must be a string, got nil");
  EXPECT_EQ(load_error(head + reference + "  takes = \"edges\" }\n"),
            "bad.lua:1: exercise: takes must be vertex, edge, face, halfedge, mesh, points or patch, got 'edges'");
  EXPECT_EQ(load_error(head + "  takes = \"edge\" }\n"), "bad.lua:1: exercise: reference must be a function, got nil");
  EXPECT_EQ(load_error(head + reference + "  takes = \"edge\", refrence = 1 }\n"),
            "bad.lua:1: exercise: unknown field 'refrence' (fields: name, title, file, call, signature, takes, allow, "
            "reference, diagnose, hint, tolerance, fixtures)");
  EXPECT_EQ(load_error(head + reference + "  takes = \"edge\", allow = { \"mesh:fly\" } }\n"),
            "bad.lua:1: exercise: allow[1] must be one of mesh:flip, mesh:split, mesh:collapse, mesh:loop_subdivide, "
            "mesh:catmull_clark, meshedit.curve, meshedit.patch, got 'mesh:fly'");
  EXPECT_EQ(load_error(head + reference +
                       "  takes = \"edge\",\n  fixtures = { { mesh = meshedit.cube(), "
                       "element = \"v0\" } } }\n"),
            "bad.lua:1: exercise: fixtures[1].element must be an edge of its mesh (a handle, an id like \"e3\", or "
            "the number), got v0");
  EXPECT_EQ(
      load_error("exercise { name = \"flip\", file = \"x.lua\", call = \"f\", takes = \"mesh\",\n" + reference + "}\n"),
      "bad.lua:1: exercise: 'flip' is a built-in exercise; choose another name");
  EXPECT_EQ(load_error("local x = nil\nx.y = 1\n"), "bad.lua:2: attempt to index a nil value (local 'x')");
  EXPECT_EQ(load_error("-- nothing\n"), "bad.lua: no exercise{} in the file");
}

TEST(ScriptedExercise, ADiagnoseThatFailsIsOneMessageNamingItsLine) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = write(dir, "failing.lua", R"lua(exercise {
  name = "failing_diagnose", file = "collapse.lua", call = "collapse_edge", takes = "edge",
  reference = function(mesh, e) return mesh:collapse(e) end,
  diagnose = function(run)
    return run.nothing.here
  end,
}
)lua");
  const Exercise id = register_scripted_exercise(ScriptedExercise::load(file));
  auto code = load_student_file(buggy());
  const auto ico = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_icosahedron()));
  const ExerciseReport report = check_exercise(*code, id, ExerciseInput::element_of(ico, EdgeId(0)));
  EXPECT_FALSE(report.equal);
  ASSERT_FALSE(report.differences.empty());
  EXPECT_EQ(
      report.differences[0].rfind("the exercise's diagnose failed: failing.lua:5: attempt to index a nil value", 0), 0u)
      << report.differences[0];
  EXPECT_NE(report.differences[1].find("has no match in the reference"), std::string::npos) << report.differences[1];
}

}  // namespace
}  // namespace meshedit
