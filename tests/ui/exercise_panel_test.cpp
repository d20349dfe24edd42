// The Exercises tab: "mine" with the correct flip matches the reference pointer for pointer (no row of the pointer
// table differs) and becomes one undoable operation; a wrong answer still reaches the document, and exactly its
// forgotten write differs, first; the pointer table of a scripted collapse; the panel drawn headless with a report
// and a replay in progress, "Run mine" clicked, an upsample's replay stepped phase by phase.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/edit_log.h"
#include "core/history.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/exercise_session.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "support/test_support.h"
#include "ui/exercise_panel.h"
#include "ui/ui_test_support.h"

namespace meshedit {
namespace {

MeshDocument cube_document() { return make_document(build_halfedge_mesh(make_cube())); }

std::filesystem::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

Selection select(ElementRef ref) {
  Selection selection;
  selection.selected = ref;
  return selection;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The solution flip with one line removed: f0 keeps pointing at a halfedge that left it.
std::string broken_flip() {
  std::string text = testing::read_text(solutions() / "flip.lua");
  const std::string line = "  f0.halfedge = h0\n";
  const size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.erase(at, line.size());
  return text;
}

Exercise collapse_exercise() {
  static const Exercise id = register_scripted_exercise(
      ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / "collapse.lua"));
  return id;
}

TEST(ExerciseSession, MineWithTheSolutionIsTheReferencePointerForPointerAndOneUndoEntry) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh original = doc.mesh;
  HalfedgeMesh expected = doc.mesh;
  ASSERT_TRUE(flip(expected, EdgeId(7)).ok());

  ExerciseSession session(solutions());
  EXPECT_EQ(session.exercise(), Exercise::FlipEdge);
  Selection selection = select(EdgeId(7));
  ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
  ASSERT_TRUE(session.last_run().has_value());
  const ExerciseRun& run = *session.last_run();
  EXPECT_EQ(run.label, "mine: flip e7");
  EXPECT_TRUE(run.report.equal);
  EXPECT_TRUE(run.report.identical);
  EXPECT_TRUE(doc.mesh.same_as(expected));
  EXPECT_EQ(doc.history.undo_depth(), 1u);
  EXPECT_EQ(doc.history.undo_label(), "mine: flip e7");
  EXPECT_EQ(doc.last.label, "mine: flip e7");
  EXPECT_FALSE(run.report.mine.edits.empty());
  EXPECT_REF(selection.selected, EdgeId(7));
  for (const PointerRow& row : pointer_rows(run, 1000)) EXPECT_FALSE(row.differs()) << format_id(row.element);

  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(original));

  // The reference, the same way.
  ASSERT_TRUE(redo(doc));
  ASSERT_TRUE(undo(doc));
  ASSERT_TRUE(session.run_reference(doc, selection).ok);
  EXPECT_EQ(session.last_run()->label, "reference: flip e7");
  EXPECT_TRUE(doc.mesh.same_as(expected));
  EXPECT_EQ(doc.history.undo_label(), "reference: flip e7");
}

TEST(ExerciseSession, TheTemplateIsDifferentAndAWrongAnswerStillReachesTheDocument) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh original = doc.mesh;
  ExerciseSession session;  // the default folder: scripts/student, the templates
  EXPECT_EQ(session.folder(), testing::source_dir() / "scripts" / "student");
  Selection selection = select(EdgeId(7));
  session.run_mine(doc, selection);
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  const ExerciseRun& run = *session.last_run();
  EXPECT_FALSE(run.report.equal);
  EXPECT_EQ(run.report.summary().rfind("different", 0), 0u) << run.report.summary();
  // The template returns nil and changes nothing: that is the student's result, and nothing is recorded.
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.history.undo_depth(), 0u);
  const std::vector<PointerRow> rows = pointer_rows(run, 1000);
  EXPECT_EQ(rows.size(), diff(original, *run.report.reference.mesh).size());
  for (const PointerRow& row : rows) {
    EXPECT_TRUE(row.differs());
    EXPECT_EQ(row.mine, row.before);
  }

  // A flip that forgets f0.halfedge: invalid and different, but the document shows it, undoably.
  const auto folder = testing::scratch_dir();
  write_file(folder / "flip.lua", broken_flip());
  session.set_folder(folder);
  session.run_mine(doc, selection);
  const ExerciseRun& broken = *session.last_run();
  EXPECT_FALSE(broken.report.equal);
  ASSERT_TRUE(broken.report.mine.validation.has_value());
  EXPECT_FALSE(broken.report.mine.validation->ok());
  EXPECT_TRUE(doc.mesh.same_as(*broken.report.mine.mesh));
  EXPECT_FALSE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.history.undo_label(), "mine: flip e7");
  EXPECT_FALSE(cached_validation(doc).ok());
  std::string red;
  const std::vector<PointerRow> broken_rows = pointer_rows(broken, 1000);
  for (const PointerRow& row : broken_rows) {
    if (row.differs()) red += format_id(row.element) + "." + row.field + " " + row.mine + " vs " + row.reference + "; ";
  }
  // Exactly the forgotten write is red: f0 of the flip (f2 on the cube) keeps its old halfedge. It comes first.
  EXPECT_EQ(red, "f2.halfedge h6 vs h8; ");
  ASSERT_GT(broken_rows.size(), 1u);
  EXPECT_TRUE(broken_rows.front().differs());
  EXPECT_EQ(format_id(broken_rows.front().element) + "." + broken_rows.front().field, "f2.halfedge");
}

TEST(ExercisePanel, DrawsAReportAndAReplayInProgress) {
  ui_testing::ImGuiHarness imgui;
  MeshDocument doc = cube_document();
  ExerciseSession session(solutions());
  ExercisePanelState state;
  state.open = true;
  Selection selection = select(EdgeId(7));
  auto draw = [&] { draw_exercise_panel(session, state, doc, selection); };
  EXPECT_GT(imgui.frame(draw), 0);  // before any run
  EXPECT_FALSE(session.last_run().has_value());

  // Clicking "Run mine" runs the student's flip on the selected edge.
  imgui.click(ImVec2(state.run_mine_x, state.run_mine_y), draw);
  session.wait_for_run(doc, selection);  // the click started it on its thread
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  EXPECT_EQ(session.last_run()->label, "mine: flip e7");
  EXPECT_EQ(doc.history.undo_label(), "mine: flip e7");
  ASSERT_TRUE(undo(doc));

  ASSERT_TRUE(session.run_mine(doc, selection).ok);
  ASSERT_TRUE(session.start_replay(doc).ok);
  ASSERT_TRUE(session.replay_step(doc, 3).ok);
  EXPECT_GT(imgui.frame(draw), 0);
  EXPECT_GT(state.writes_drawn, 3u);
  EXPECT_EQ(state.rows_serial, session.last_run()->serial);
  EXPECT_FALSE(state.rows.empty());
  EXPECT_TRUE(session.replaying());  // drawing does not end the replay
  EXPECT_EQ(session.replay_position(), 3u);

  // The template: a report with differences and red rows.
  session.finish_replay(doc);
  session.set_folder(testing::source_dir() / "scripts" / "student");
  session.run_mine(doc, selection);
  EXPECT_GT(imgui.frame(draw), 0);
  EXPECT_FALSE(state.rows.empty());
  EXPECT_TRUE(state.rows.front().differs());
  state.open = false;
  imgui.frame(draw);
}

// An upsample's replay goes phase by phase: "replay by phase" starts at phase 1 (nothing written), "next phase" jumps
// to the first split, then to the first flip; the table holds yours beside the reference at each boundary.
TEST(ExercisePanel, NextPhaseJumpsTheUpsampleReplayToEachPhasesFirstWrite) {
  ui_testing::ImGuiHarness imgui;
  MeshDocument doc = cube_document();
  const HalfedgeMesh before = doc.mesh;
  ExerciseSession session(solutions());
  ASSERT_TRUE(session.set_exercise(Exercise::Upsample));
  ExercisePanelState state;
  state.open = true;
  Selection none;
  auto draw = [&] { draw_exercise_panel(session, state, doc, none); };
  ASSERT_TRUE(session.run_mine(doc, none).ok) << doc.message.text;
  EXPECT_GT(imgui.frame(draw), 0);
  ASSERT_TRUE(state.phases.has_value());
  ASSERT_TRUE(state.phase_states.has_value());
  EXPECT_EQ(state.phases_serial, session.last_run()->serial);
  for (int p = 1; p <= 4; ++p) EXPECT_TRUE(state.phase_states->at[size_t(p)].identical()) << p;
  EXPECT_FALSE(session.replaying());

  const size_t E = 18;
  const size_t expected[] = {0, 1, E + 1, state.phases->span[4].first + 1};
  for (const size_t k : expected) {
    imgui.click(ImVec2(state.next_phase_x, state.next_phase_y), draw);
    ASSERT_TRUE(session.replaying()) << doc.message.text;
    EXPECT_EQ(session.replay_position(), k);
    EXPECT_TRUE(doc.mesh.same_as(replay(before, session.edits(), k)));
  }
  EXPECT_EQ(state.phases->phase_at(session.replay_position()), UpsamplePhase::Commit);
  // Past the last phase the button does nothing.
  imgui.click(ImVec2(state.next_phase_x, state.next_phase_y), draw);
  EXPECT_EQ(session.replay_position(), expected[3]);
  session.finish_replay(doc);
  EXPECT_EQ(doc.history.undo_depth(), 1u);

  // A flip run has no phases.
  ASSERT_TRUE(session.set_exercise(Exercise::FlipEdge));
  Selection edge = select(EdgeId(7));
  ASSERT_TRUE(session.run_mine(doc, edge).ok);
  imgui.frame(draw);
  EXPECT_FALSE(state.phases.has_value());
}

// The pointer table of a collapse: no row for an element both deleted; the position the buggy collapse left is a row
// that differs, among the first.
TEST(ScriptedExerciseSession, ThePointerTableOfACollapseShowsWhatDiffers) {
  const Exercise id = collapse_exercise();
  const std::filesystem::path dir = testing::scratch_dir();
  std::filesystem::copy_file(testing::source_dir() / "tests" / "grading" / "scripted" / "collapse_keeps_position.lua",
                             dir / "collapse.lua");
  MeshDocument doc = make_document(build_halfedge_mesh(make_icosahedron()));
  ExerciseSession session(dir);
  ASSERT_TRUE(session.set_exercise(id));
  Selection selection;
  selection.selected = EdgeId(0);
  ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
  const ExerciseRun& run = *session.last_run();
  EXPECT_FALSE(run.report.equal);
  const std::vector<PointerRow> rows = pointer_rows(run, 1000);
  ASSERT_FALSE(rows.empty());
  const HalfedgeMesh& mine = *run.report.mine.mesh;
  const HalfedgeMesh& reference = *run.report.reference.mesh;
  for (const PointerRow& row : rows) {
    EXPECT_TRUE(mine.alive(row.element) || reference.alive(row.element)) << format_id(row.element) << "." << row.field;
  }
  const std::string kept = format_id(run.report.mine.element);
  const auto position = std::find_if(rows.begin(), rows.end(), [&](const PointerRow& row) {
    return format_id(row.element) == kept && row.field == "position";
  });
  ASSERT_NE(position, rows.end());
  EXPECT_TRUE(position->differs());
  EXPECT_EQ(position->mine, position->before);  // it stayed where a was
  EXPECT_TRUE(std::all_of(rows.begin(), position, [](const PointerRow& row) { return row.differs(); }));
}

}  // namespace
}  // namespace meshedit
