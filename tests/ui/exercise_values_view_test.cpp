// The Exercises tab on a scripted exercise on points or a patch (ui/exercise_values_view.h): a run on a fixture leaves
// the document as it was and says its verdict in the status line; the rows put yours beside the reference's, item by
// item, the differing ones marked; the input reads as text; the lesson's input replaces the fixture until another is
// chosen; and the panel draws such a run headless.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/exercise_session.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "support/test_support.h"
#include "ui/exercise_panel.h"
#include "ui/exercise_values_view.h"
#include "ui/ui_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

Exercise registered(const std::string& name) {
  return register_scripted_exercise(ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / name));
}

// A student folder holding `file` as NAME.lua.
fs::path folder_with(const fs::path& file, const std::string& name) {
  const fs::path dir = testing::scratch_dir();
  fs::copy_file(file, dir / name, fs::copy_options::overwrite_existing);
  return dir;
}

fs::path buggy(const std::string& name) { return testing::source_dir() / "tests" / "grading" / "scripted" / name; }
fs::path solution(const std::string& name) { return testing::source_dir() / "tests" / "exercise" / "solutions" / name; }

TEST(ValuesExerciseSession, ARunOnAFixtureLeavesTheDocumentAndListsBothResults) {
  const Exercise id = registered("hodograph.lua");
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
  const HalfedgeMesh before = doc.mesh;
  ExerciseSession session(folder_with(buggy("hodograph_no_factor.lua"), "hodograph.lua"));
  ASSERT_TRUE(session.set_exercise(id));
  EXPECT_FALSE(session.set_fixture(99));
  Selection none;
  EXPECT_TRUE(session.run_mine(doc, none).ok) << "a wrong answer ran: " << doc.message.text;
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  const ExerciseRun& run = *session.last_run();
  EXPECT_EQ(run.label, "mine: hodograph (a cubic in the plane)");
  EXPECT_FALSE(run.report.equal);
  EXPECT_FALSE(run.applied);
  EXPECT_TRUE(doc.mesh.same_as(before));
  EXPECT_EQ(doc.history.undo_depth(), 0u);
  EXPECT_EQ(doc.message.text.rfind("mine: hodograph (a cubic in the plane): different: your points are the "
                                   "differences P[i+1] - P[i] without the factor n",
                                   0),
            0u)
      << doc.message.text;

  const std::vector<ValueRow> rows = value_rows(run);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].what, "point 1");
  EXPECT_EQ(rows[0].mine, "(1, 2, 0)");
  EXPECT_EQ(rows[0].reference, "(3, 6, 0)");
  EXPECT_TRUE(rows[0].differs);
  EXPECT_EQ(value_input_lines(run),
            (std::vector<std::string>{"P0 (0, 0, 0)", "P1 (1, 2, 0)", "P2 (3, 3, 0)", "P3 (4, 0, 0)"}));

  // The line (n = 1): the same code is right there.
  ASSERT_TRUE(session.set_fixture(3));
  EXPECT_TRUE(session.run_mine(doc, none).ok) << doc.message.text;
  EXPECT_TRUE(session.last_run()->report.equal);
  const std::vector<ValueRow> line = value_rows(*session.last_run());
  ASSERT_EQ(line.size(), 1u);
  EXPECT_EQ(line[0].mine, "(2, 1, 0)");
  EXPECT_FALSE(line[0].differs);

  // The reference alone.
  EXPECT_TRUE(session.run_reference(doc, none).ok);
  EXPECT_EQ(doc.message.text, "reference: hodograph (a line (degree 1)): returned a list of 1 point");
}

TEST(ValuesExerciseSession, ALessonsInputReplacesTheFixtureUntilAnotherIsChosen) {
  const Exercise id = registered("patch_normal.lua");
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
  ExerciseSession session(folder_with(solution("patch_normal.lua"), "patch_normal.lua"));
  ASSERT_TRUE(session.set_exercise(id));
  const ScriptedExercise& definition = *id.definition();
  ExerciseInput input = definition.input_of(definition.fixtures()[0]);
  input.args = {ExerciseValue::of_number(0.25), ExerciseValue::of_number(0.75)};
  session.set_values_input(input, "the lesson's input");
  Selection none;
  ASSERT_TRUE(session.run_mine(doc, none).ok) << doc.message.text;
  EXPECT_EQ(session.last_run()->label, "mine: patch_normal (the lesson's input)");
  const std::vector<std::string> lines = value_input_lines(*session.last_run());
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "row 0: (0, 0, 0) (1, 0, 0) (2, 0, 0) (3, 0, 0)");
  EXPECT_EQ(lines[4], "args: 0.25, 0.75");
  const std::vector<ValueRow> rows = value_rows(*session.last_run());
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].what, "returned");
  EXPECT_EQ(rows[0].reference, "(0, 0, 1)");
  ASSERT_TRUE(session.set_fixture(1));
  EXPECT_FALSE(session.has_values_input());
  ASSERT_TRUE(session.run_mine(doc, none).ok);
  EXPECT_EQ(session.last_run()->label, "mine: patch_normal (a bump, off its middle)");
}

TEST(ValuesExercisePanel, DrawsARunOnValues) {
  ui_testing::ImGuiHarness imgui;
  const Exercise id = registered("hodograph.lua");
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
  ExerciseSession session(folder_with(buggy("hodograph_reversed.lua"), "hodograph.lua"));
  ASSERT_TRUE(session.set_exercise(id));
  ExercisePanelState state;
  state.open = true;
  Selection none;
  auto draw = [&] { draw_exercise_panel(session, state, doc, none); };
  EXPECT_GT(imgui.frame(draw), 0);  // before any run: the fixture chooser
  imgui.click(ImVec2(state.run_mine_x, state.run_mine_y), draw);
  session.wait_for_run(doc, none);  // the click started it on its thread
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  EXPECT_GT(imgui.frame(draw), 0);
  ASSERT_EQ(state.value_rows.size(), 3u);
  EXPECT_TRUE(state.value_rows[0].differs);
  EXPECT_TRUE(state.rows.empty()) << "no pointer table without a mesh";
  EXPECT_EQ(session.replay_length(), 0u);
}

}  // namespace
}  // namespace meshedit
