// A runaway upsample is stopped and explained with the line it was on (upsample_runaway.h, through check_exercise,
// what the Exercises tab and the grader's expect.exercise say): a loop that splits the edges its own splits made
// (tests/grading/students/upsample_splits_new_edges.lua) and a `while true do end`, with the recording every
// upsample run gets and from the mesh alone.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "exercise/exercises.h"
#include "exercise/internal/upsample_runaway.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Mesh = std::shared_ptr<const HalfedgeMesh>;

Mesh cube() { return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_cube())); }

std::string fixture() {
  return testing::read_text(testing::source_dir() / "tests/grading/students/upsample_splits_new_edges.lua");
}

// "upsample.lua:N" of the first line of `text` that contains `words`.
std::string line_of(const std::string& text, const std::string& words) {
  const size_t at = text.find(words);
  EXPECT_NE(at, std::string::npos) << words;
  return "upsample.lua:" + std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
}

ExerciseReport check(const std::string& text, bool record, LuaLimits limits = {}) {
  const auto path = testing::scratch_dir() / "upsample.lua";
  std::ofstream(path, std::ios::binary) << text;
  auto code = load_student_file(path, limits);
  RunOptions options;
  options.record_edits = record;
  return check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(cube()), options);
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST(UpsampleRunaway, TheBudgetFollowsTheMeshAndStaysUnderTheRecordersCap) {
  EXPECT_EQ(upsample_edit_budget(*cube()), 64u * (8 + 18 + 12) + 4096);
  HalfedgeMesh big = build_halfedge_mesh(make_grid(300, 300));
  EXPECT_EQ(upsample_edit_budget(big), size_t(1) << 20);
}

// As the Exercises tab and the lessons run it (default limits; an upsample is always recorded): stopped by the
// recording's budget, at the line of the split, and told what it was doing.
TEST(UpsampleRunaway, SplittingTheEdgesItsSplitsMadeIsStoppedAtTheSplitsLine) {
  const std::string text = fixture();
  const ExerciseReport r = check(text, false);
  ASSERT_FALSE(r.mine.ran);
  EXPECT_EQ(r.mine.edits.size(), upsample_edit_budget(*cube()));
  ASSERT_EQ(r.differences.size(), 2u);
  const std::string split_line = line_of(text, "local m = mesh:split(o.edge)");
  const std::string budget = std::to_string(upsample_edit_budget(*cube()));
  EXPECT_EQ(r.differences[0], split_line + ": more than " + budget +
                                  " changes recorded; is there a loop that never ends? It was "
                                  "stopped in phase 2 (edges split) after " +
                                  budget +
                                  " splits; the mesh had 18 edges and Loop "
                                  "subdivision splits each of them once: the loop at " +
                                  split_line +
                                  " splits edges that its own splits "
                                  "made. List the original edges before the first split and split only those.");
  EXPECT_EQ(r.differences[1], unfinished_run_hint(Exercise::Upsample));
  EXPECT_EQ(r.summary(), "different: " + r.differences[0] + " (1 more)");
}

// Without a recording (explain_unfinished_upsample given only the mesh a stopped run left): the splits are counted
// from the mesh.
TEST(UpsampleRunaway, WithoutARecordingTheSplitsAreCountedFromTheMesh) {
  const ExerciseReport r = check(fixture(), true);
  ASSERT_TRUE(r.mine.mesh);
  const size_t splits = r.mine.mesh->num_vertices() - 8;
  EXPECT_GT(splits, 18u);
  const std::string error = "upsample.lua:38: instruction budget exceeded (2000000 instructions)";
  const std::string text = explain_unfinished_upsample(error, *cube(), r.mine.mesh.get(), {});
  EXPECT_TRUE(starts_with(text, error + ". It was stopped after ")) << text;
  EXPECT_NE(text.find(std::to_string(splits) + " splits (one new vertex each); the mesh had 18 edges"),
            std::string::npos)
      << text;
}

TEST(UpsampleRunaway, AWhileTrueIsStoppedAtItsLineBeforeItChangedTheMesh) {
  const std::string text = "function upsample(mesh)\n  local n = 0\n  while true do\n    n = n + 1\n  end\nend\n";
  LuaLimits limits;
  limits.instructions = 1'000'000;
  for (const bool record : {true, false}) {
    const ExerciseReport r = check(text, record, limits);
    ASSERT_EQ(r.differences.size(), 2u);
    const std::string& first = r.differences[0];
    // The hook stops it on one of the loop's lines.
    EXPECT_TRUE(starts_with(first, "upsample.lua:3:") || starts_with(first, "upsample.lua:4:")) << first;
    const std::string at = first.substr(0, first.find(": "));
    EXPECT_NE(first.find("instruction budget exceeded (1000000 instructions). It was stopped before it changed the "
                         "mesh: a loop at " +
                         at + " never ends. Look at what its condition waits for"),
              std::string::npos)
        << first;
    EXPECT_EQ(r.differences[1], unfinished_run_hint(Exercise::Upsample));
  }
}

TEST(UpsampleRunaway, AnErrorWithoutALineTakesTheLastWritesLine) {
  RecordedEdit split;
  split.what = EditKind::Operation;
  split.field = "split";
  split.element = EdgeId(0);
  split.where = "upsample.lua:7";
  const HalfedgeMesh before = *cube();
  const std::vector<RecordedEdit> edits(30, split);
  const std::string text = explain_unfinished_upsample("time limit exceeded (5 s)", before, nullptr, edits);
  EXPECT_TRUE(starts_with(text,
                          "upsample.lua:7: time limit exceeded (5 s). It was stopped in phase 2 (edges split) "
                          "after 30 splits;"))
      << text;
}

}  // namespace
}  // namespace meshedit
