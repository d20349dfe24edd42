// The Exercises tab with an exercise defined in Lua (scripts/exercises/collapse.lua): it is listed after the
// built-in mesh exercises; Run mine on a selected edge of an icosahedron puts the student's collapse in the document
// as one undo entry, right against the definition's reference; the replay steps through the student's writes; a
// selection of the wrong kind is refused as flip and split refuse it; a definition saved while the window runs is
// loaded again at the next run.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/exercise_session.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

Exercise collapse_exercise() {
  static const Exercise id = register_scripted_exercise(
      ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / "collapse.lua"));
  return id;
}

std::filesystem::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

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
  EXPECT_TRUE(
      testing::near(doc.mesh.position(VertexId(run.report.mine.element.index)), expected.position(kept.value), 1e-12));
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

// An instructor saves the definition while the window runs: the next run uses the new version, and a version that
// does not load is refused with its file:line, the last good one staying registered.
TEST(ScriptedExerciseSession, ASavedDefinitionIsReloadedAtTheNextRun) {
  const std::filesystem::path dir = testing::scratch_dir();
  const std::string original = testing::read_text(testing::source_dir() / "scripts" / "exercises" / "collapse.lua");
  const auto save = [&](const std::string& text) { std::ofstream(dir / "collapse.lua", std::ios::binary) << text; };
  save(original);
  const Exercise id = register_scripted_exercise(ScriptedExercise::load(dir / "collapse.lua"));
  ExerciseSession session(solutions());
  ASSERT_TRUE(session.set_exercise(id));
  MeshDocument doc = make_document(build_halfedge_mesh(make_icosahedron()));
  Selection selection;
  selection.selected = EdgeId(0);

  std::string broken = original;
  const std::string takes = "takes = \"edge\"";
  broken.replace(broken.find(takes), takes.size(), "takes = \"edges\"");
  save(broken);
  const Check refused = session.run_mine(doc, selection);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason.rfind("the exercise's definition did not load: collapse.lua:", 0), 0u) << refused.reason;
  EXPECT_NE(
      refused.reason.find("exercise: takes must be vertex, edge, face, halfedge, mesh, points or patch, got 'edges'"),
      std::string::npos)
      << refused.reason;
  EXPECT_EQ(doc.history.undo_depth(), 0u);
  EXPECT_STREQ(exercise_info(id).title, "Extra: edge collapse");  // the last good version

  std::string retitled = original;
  const std::string title = "Extra: edge collapse";
  retitled.replace(retitled.find(title), title.size(), "Edge collapse, saved");
  save(retitled);
  ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
  EXPECT_STREQ(exercise_info(id).title, "Edge collapse, saved");
  EXPECT_TRUE(session.last_run()->report.equal);
  EXPECT_EQ(doc.mesh.num_vertices(), 11u);
  register_scripted_exercise(
      ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / "collapse.lua"));  // as it was
}

}  // namespace
}  // namespace meshedit
