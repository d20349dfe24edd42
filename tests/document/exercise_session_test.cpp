// The window's exercise session: the replay shows exactly replay(before, edits, k) with the k-th write as the only
// highlighted cell and adds no history, and is dropped when the document changes elsewhere; a saved file is
// reloaded; a syntax error names file:line and changes nothing; a student's own "memory ran out" is the student's
// error; the selection must fit the exercise; a flip that loops over a big mesh is told so; an upsample runs on the
// whole mesh; show_state keeps history. Runs read through the Exercises tab's pointer table are tested with the
// panel (ui/exercise_panel_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <fstream>
#include <string>

#include "core/edit_log.h"
#include "core/history.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/document_test_support.h"
#include "document/exercise_session.h"
#include "support/test_support.h"

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

// The solution flip with `line` put in front of its first line or of its `return e`.
std::string solution_flip_with(const std::string& line, bool before_return) {
  std::string text = testing::read_text(solutions() / "flip.lua");
  const std::string anchor = before_return ? "  return e\n" : "function flip_edge(mesh, e)\n";
  const size_t at = text.find(anchor);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.insert(before_return ? at : at + anchor.size(), line + "\n");
  return text;
}

// The line of `text` (from 1) holding `needle`.
int line_of(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

TEST(ExerciseSession, ReplayShowsEachStateWithItsWriteAndAddsNoHistory) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh before = doc.mesh;
  ExerciseSession session(solutions());
  Selection selection = select(EdgeId(7));
  ASSERT_TRUE(session.run_mine(doc, selection).ok);
  const HalfedgeMesh after = doc.mesh;
  const std::vector<RecordedEdit> edits = session.edits();
  ASSERT_GE(edits.size(), 10u);
  EXPECT_FALSE(session.replaying());
  EXPECT_FALSE(session.replay_step(doc, 1).ok);  // not started

  ASSERT_TRUE(session.start_replay(doc).ok);
  EXPECT_TRUE(session.replaying());
  EXPECT_TRUE(doc.mesh.same_as(before));
  EXPECT_EQ(doc.last.change_count, 0u);
  EXPECT_EQ(session.replay_length(), edits.size());
  size_t highlighted = 0;
  for (size_t k = 0; k <= edits.size(); ++k) {
    ASSERT_TRUE(session.replay_step(doc, k).ok);
    session.sync(doc);
    ASSERT_TRUE(session.replaying()) << k;
    EXPECT_EQ(session.replay_position(), k);
    EXPECT_TRUE(doc.mesh.same_as(replay(before, edits, k))) << k;
    EXPECT_EQ(doc.history.undo_depth(), 1u);
    if (k == 0) continue;
    const RecordedEdit& edit = edits[k - 1];
    ASSERT_EQ(edit.what, EditKind::Set) << describe(edit);
    const bool changes = format_edit_before(edit) != format_edit_after(edit);
    EXPECT_EQ(doc.last.change_count, changes ? 1u : 0u) << k << ": " << describe(edit);
    if (changes) {
      ++highlighted;
      EXPECT_TRUE(doc.last.index.contains(edit.element, *parse_field(edit.field))) << describe(edit);
      EXPECT_EQ(doc.last.changes[0].after, format_edit_after(edit));
    }
    EXPECT_NE(doc.last.label.find(describe(edit)), std::string::npos) << doc.last.label;
  }
  EXPECT_GT(highlighted, 0u);
  // Backwards is as exact as forwards.
  ASSERT_TRUE(session.replay_step(doc, 2).ok);
  EXPECT_TRUE(doc.mesh.same_as(replay(before, edits, 2)));
  EXPECT_EQ(session.replay_step(doc, 999).ok, true);
  EXPECT_EQ(session.replay_position(), edits.size());

  session.finish_replay(doc);
  EXPECT_FALSE(session.replaying());
  EXPECT_TRUE(doc.mesh.same_as(after));
  EXPECT_EQ(doc.history.undo_depth(), 1u);
  EXPECT_EQ(doc.last.label, "mine: flip e7");
  EXPECT_EQ(doc.last.change_count, diff(before, after).size());
  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(before));
  EXPECT_FALSE(doc.history.can_undo());
}

TEST(ExerciseSession, AReplayIsDroppedWhenTheDocumentChangesElsewhere) {
  MeshDocument doc = cube_document();
  ExerciseSession session(solutions());
  Selection selection = select(EdgeId(7));
  ASSERT_TRUE(session.run_mine(doc, selection).ok);
  ASSERT_TRUE(apply_operation(doc, "flip e3", [](HalfedgeMesh& m) { return flip(m, EdgeId(3)); }).ok());
  EXPECT_FALSE(session.can_replay(doc));  // the document no longer shows the run's result
  EXPECT_FALSE(session.start_replay(doc).ok);

  ASSERT_TRUE(undo(doc));
  ASSERT_TRUE(session.run_mine(doc, selection).ok);
  ASSERT_TRUE(session.start_replay(doc).ok);
  ASSERT_TRUE(session.replay_step(doc, 3).ok);
  replace_mesh(doc, build_halfedge_mesh(make_cube()), "");
  session.sync(doc);
  EXPECT_FALSE(session.replaying());
  const HalfedgeMesh fresh = doc.mesh;
  session.finish_replay(doc);  // nothing to finish: the new mesh stays
  EXPECT_TRUE(doc.mesh.same_as(fresh));
}

TEST(ExerciseSession, ASavedFileIsReloadedOnTheNextRun) {
  const auto folder = testing::scratch_dir();
  write_file(folder / "flip.lua", "function flip_edge(mesh, e) print('one') return nil end\n");
  MeshDocument doc = cube_document();
  ExerciseSession session(folder);
  Selection selection = select(EdgeId(7));
  session.run_mine(doc, selection);
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  EXPECT_EQ(session.last_run()->report.mine.output, std::vector<std::string>{"one"});
  EXPECT_EQ(session.loads(), 1u);
  session.run_mine(doc, selection);
  EXPECT_EQ(session.loads(), 1u);  // unchanged: not loaded again
  EXPECT_FALSE(session.file_changed());

  write_file(folder / "flip.lua", solution_flip_with("  print('two', 2)", false));
  // Some file systems keep whole seconds: move the time on so the test does not depend on them.
  std::filesystem::last_write_time(folder / "flip.lua",
                                   std::filesystem::last_write_time(folder / "flip.lua") + std::chrono::seconds(2));
  EXPECT_TRUE(session.file_changed());
  session.run_mine(doc, selection);
  EXPECT_EQ(session.loads(), 2u);
  EXPECT_EQ(session.last_run()->report.mine.output, std::vector<std::string>{"two\t2"});
  EXPECT_TRUE(session.last_run()->report.equal);
  EXPECT_EQ(doc.history.undo_label(), "mine: flip e7");
}

TEST(ExerciseSession, ASyntaxErrorNamesFileAndLineAndChangesNothing) {
  const auto folder = testing::scratch_dir();
  write_file(folder / "flip.lua", "function flip_edge(mesh, e)\n  local x = (\nend\n");
  MeshDocument doc = cube_document();
  const HalfedgeMesh original = doc.mesh;
  const uint64_t version = doc.mesh.version();
  ExerciseSession session(folder);
  Selection selection = select(EdgeId(7));
  const Check check = session.run_mine(doc, selection);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(session.load_error().rfind("flip.lua:3:", 0), 0u) << session.load_error();
  EXPECT_EQ(check.reason, session.load_error());
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, session.load_error());
  EXPECT_FALSE(session.last_run().has_value());
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.mesh.version(), version);
  EXPECT_EQ(doc.history.undo_depth(), 0u);
}

// A student's error that says "memory ran out" is the student's error: the run goes in as "mine (error)" with a
// Warning, as any other error half way (memory really running out is told by a flag: tests/out_of_memory).
TEST(ExerciseSession, AStudentsOwnMemoryRanOutErrorIsTheStudentsError) {
  const auto folder = testing::scratch_dir();
  const std::string text = solution_flip_with("  error('memory ran out')", true);
  write_file(folder / "flip.lua", text);
  const std::string error = "flip.lua:" + std::to_string(line_of(text, "error('memory ran out')")) + ": memory ran out";
  MeshDocument doc = cube_document();
  HalfedgeMesh flipped = doc.mesh;
  ASSERT_TRUE(flip(flipped, EdgeId(7)).ok());
  ExerciseSession session(folder);
  Selection selection = select(EdgeId(7));
  const Check check = session.run_mine(doc, selection);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.reason, error);
  ASSERT_TRUE(session.last_run().has_value()) << doc.message.text;
  const ExerciseRun& run = *session.last_run();
  EXPECT_EQ(run.label, "mine (error): flip e7");
  EXPECT_EQ(run.report.mine.error, error);
  EXPECT_FALSE(run.report.mine.out_of_memory);
  EXPECT_TRUE(run.applied);
  EXPECT_TRUE(doc.mesh.same_as(flipped));  // what it did before the error goes in
  EXPECT_EQ(doc.history.undo_label(), "mine (error): flip e7");
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_NE(doc.message.text.find(error), std::string::npos) << doc.message.text;
}

TEST(ExerciseSession, TheSelectionMustFitTheExercise) {
  MeshDocument doc = cube_document();
  ExerciseSession session(solutions());
  Selection none;
  EXPECT_FALSE(session.run_mine(doc, none).ok);
  EXPECT_FALSE(session.last_run().has_value());
  EXPECT_FALSE(session.set_exercise(Exercise::CurveStep));
  ASSERT_TRUE(session.set_exercise(Exercise::VertexNormal));
  EXPECT_EQ(session.file(), solutions() / "normals.lua");
  Selection edge = select(EdgeId(7));
  EXPECT_FALSE(session.run_mine(doc, edge).ok);
  Selection vertex = select(VertexId(3));
  ASSERT_TRUE(session.run_mine(doc, vertex).ok) << doc.message.text;
  EXPECT_EQ(session.last_run()->label, "mine: normal v3");
  EXPECT_TRUE(session.last_run()->report.equal);
  EXPECT_EQ(doc.history.undo_depth(), 0u);  // a normal changes no pointer
}

// The Exercises tab's verdict is compare()'s, locality bound included: a flip that loops over the halfedges of an
// 80x70 grid first is wrong there, in the words the grader uses, and its writes still replay.
TEST(ExerciseSession, AFlipThatLoopsOverABigMeshIsToldHowManyElementsItTouched) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_grid(80, 70)));
  EdgeId middle;
  for (EdgeId e : doc.mesh.edges()) {
    const glm::dvec3 p = doc.mesh.position(doc.mesh.vertex(doc.mesh.halfedge(e)));
    const glm::dvec3 q = doc.mesh.position(doc.mesh.vertex(doc.mesh.twin(doc.mesh.halfedge(e))));
    if (p + q == glm::dvec3(81, 71, 0)) middle = e;  // the diagonal from (40, 35) to (41, 36)
  }
  ASSERT_TRUE(middle.valid());
  const std::filesystem::path folder = testing::scratch_dir();
  write_file(folder / "flip.lua", solution_flip_with("  for h in mesh:halfedges() do end", false));
  ExerciseSession session(folder);
  Selection selection = select(middle);
  ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
  const ExerciseReport& report = session.last_run()->report;
  ASSERT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 1u) << report.summary();
  EXPECT_EQ(report.differences[0].rfind("your flip_edge touched ", 0), 0u) << report.differences[0];
  EXPECT_NE(report.differences[0].find(" elements of a mesh of 11200 faces (it wrote "), std::string::npos)
      << report.differences[0];
  EXPECT_GT(report.mine.touched->elements, doc.mesh.num_halfedges());
  EXPECT_TRUE(session.can_replay(doc));
}

TEST(ExerciseSession, UpsampleRunsOnTheWholeMeshAndReplaysItsCreations) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh before = doc.mesh;
  ExerciseSession session(solutions());
  ASSERT_TRUE(session.set_exercise(Exercise::Upsample));
  Selection none;
  ASSERT_TRUE(session.run_mine(doc, none).ok) << doc.message.text;
  EXPECT_EQ(session.last_run()->label, "mine: upsample");
  EXPECT_TRUE(session.last_run()->report.equal) << session.last_run()->report.summary();
  EXPECT_EQ(doc.mesh.num_faces(), 4 * before.num_faces());
  EXPECT_EQ(doc.history.undo_depth(), 1u);
  const HalfedgeMesh after = doc.mesh;
  const size_t n = session.replay_length();
  ASSERT_GT(n, 0u);
  ASSERT_TRUE(session.start_replay(doc).ok);
  ASSERT_TRUE(session.replay_step(doc, n / 2).ok);
  EXPECT_TRUE(doc.mesh.same_as(replay(before, session.edits(), n / 2)));
  ASSERT_TRUE(session.replay_step(doc, n).ok);
  EXPECT_TRUE(doc.mesh.same_as(after));
  session.finish_replay(doc);
  EXPECT_TRUE(doc.mesh.same_as(after));
  EXPECT_EQ(doc.history.undo_depth(), 1u);
}

TEST(ShowState, ReplacesTheMeshAndLastButKeepsHistory) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh original = doc.mesh;
  ASSERT_TRUE(apply_operation(doc, "flip e7", [](HalfedgeMesh& m) { return flip(m, EdgeId(7)); }).ok());
  const uint64_t generation = doc.generation;
  const uint64_t version = doc.mesh.version();
  const uint64_t serial = doc.last.serial;
  show_state(doc, original, "back");
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_GT(doc.mesh.version(), version);
  EXPECT_EQ(doc.generation, generation);
  EXPECT_EQ(doc.history.undo_depth(), 1u);
  EXPECT_EQ(doc.history.undo_label(), "flip e7");
  EXPECT_EQ(doc.last.label, "back");
  EXPECT_EQ(doc.last.serial, serial + 1);
  EXPECT_EQ(doc.last.change_count, 12u);  // the flip's 12 fields, backwards
  show_state(doc, original, "same", original);
  EXPECT_EQ(doc.last.change_count, 0u);
}

}  // namespace
}  // namespace meshedit
