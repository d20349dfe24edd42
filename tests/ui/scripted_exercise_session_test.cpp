// The Exercises tab with an exercise defined in Lua (scripts/exercises/collapse.lua): it is listed after the
// built-in mesh exercises; Run mine on a selected edge of an icosahedron puts the student's collapse in the document
// as one undo entry, right against the definition's reference; the replay steps through the student's writes; a
// selection of the wrong kind is refused as flip and split refuse it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "script/scripted_exercise.h"
#include "support/test_support.h"
#include "ui/exercise_session.h"

namespace meshedit {
namespace {

Exercise collapse_exercise() {
  static const Exercise id = register_scripted_exercise(
      ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / "collapse.lua"));
  return id;
}

std::filesystem::path solutions() { return testing::source_dir() / "tests" / "script" / "solutions"; }

TEST(ScriptedExerciseSession, TheExercisesTabRunsAndReplaysACollapse) {
  const Exercise id = collapse_exercise();
  const std::vector<Exercise> listed = mesh_exercises();
  EXPECT_EQ(listed.front(), Exercise::VertexNormal);
  EXPECT_NE(std::find(listed.begin(), listed.end(), id), listed.end());

  MeshDocument doc = make_document(build_halfedge_mesh(make_icosahedron()));
  HalfedgeMesh expected = doc.mesh;
  const OpResult<VertexId> kept = collapse(expected, EdgeId(0));
  ASSERT_TRUE(kept.ok());
  ExerciseSession session(solutions());
  ASSERT_TRUE(session.set_exercise(id));
  EXPECT_EQ(session.file(), solutions() / "collapse.lua");
  Selection selection;
  selection.selected = EdgeId(0);
  ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
  const ExerciseRun& run = *session.last_run();
  EXPECT_EQ(run.label, "mine: collapse e0");
  EXPECT_TRUE(run.report.equal) << run.report.summary();
  EXPECT_EQ(doc.mesh.num_vertices(), 11u);
  EXPECT_EQ(doc.mesh.num_faces(), 18u);
  EXPECT_TRUE(testing::near(doc.mesh.position(VertexId(run.report.mine.element.index)), expected.position(kept.value),
                            1e-12));
  EXPECT_EQ(doc.history.undo_depth(), 1u);

  ASSERT_TRUE(session.can_replay(doc));
  const size_t writes = session.replay_length();
  EXPECT_GT(writes, 10u);
  ASSERT_TRUE(session.start_replay(doc).ok);
  EXPECT_EQ(doc.mesh.num_vertices(), 12u);  // before the first write
  ASSERT_TRUE(session.replay_step(doc, writes).ok);
  EXPECT_EQ(doc.mesh.num_vertices(), 11u);
  session.finish_replay(doc);
  EXPECT_EQ(doc.history.undo_depth(), 1u);

  selection.selected = VertexId(3);
  const Check refused = session.run_mine(doc, selection);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason, "v3 is a vertex; select an edge (or one of its halfedges) first");
}

}  // namespace
}  // namespace meshedit
