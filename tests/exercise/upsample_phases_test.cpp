// The phases of a recorded upsample (upsample_phases.h) and the meshes at their boundaries beside the reference's
// (upsample_phase_states.h), on real recordings: the correct solution (through mesh:split and mesh:flip, and with a
// split and a flip written by hand), the buggy fixtures of tests/grading/students, and variants that interleave or
// skip phases. At every boundary yours is held against the core's phases (loop_subdivision.h) pointer for pointer.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_compare.h"
#include "core/primitives.h"
#include "exercise/exercises.h"
#include "exercise/upsample_phase_states.h"
#include "exercise/upsample_phases.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Mesh = std::shared_ptr<const HalfedgeMesh>;

Mesh mesh_of(const PolygonMesh& p) { return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(p)); }

std::string solution_text() {
  return testing::read_text(testing::source_dir() / "tests/exercise/solutions/upsample.lua");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not in the text: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// "upsample.lua:N" of the first line of `text` that contains `words`.
std::string line_of(const std::string& text, const std::string& words) {
  const size_t at = text.find(words);
  EXPECT_NE(at, std::string::npos) << words;
  return "upsample.lua:" + std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
}

struct Recording {
  Mesh before;
  ExerciseReport report;
  const std::vector<RecordedEdit>& edits() const { return report.mine.edits; }
};

Recording record(const std::string& text, Mesh mesh, LuaLimits limits = {}) {
  const auto path = testing::scratch_dir() / "upsample.lua";
  std::ofstream(path, std::ios::binary) << text;
  auto code = load_student_file(path, limits);
  RunOptions options;
  options.record_edits = true;
  return {mesh, check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(mesh), options)};
}

// The core's mesh after phase p (1-4) of Loop subdivision of `before`.
HalfedgeMesh reference_after(const HalfedgeMesh& before, int p) {
  OpResult<LoopState> state = loop_compute_positions(before);
  EXPECT_TRUE(state.ok()) << state.check.reason;
  HalfedgeMesh mesh = before;
  if (p >= 2) loop_split_edges(mesh, state.value);
  if (p >= 3) loop_flip_edges(mesh, state.value);
  if (p >= 4) loop_commit_positions(mesh, state.value);
  return mesh;
}

// Yours at the end of phase p, replayed from the recording.
HalfedgeMesh yours_after(const Recording& r, const UpsamplePhases& phases, int p) {
  return replay(*r.before, r.edits(), phases.end_position(UpsamplePhase(p)));
}

void expect_identical_at_every_boundary(const Recording& r, const UpsamplePhases& phases) {
  for (int p = 1; p <= 4; ++p) {
    const MeshComparison c = compare_meshes_exact(yours_after(r, phases, p), reference_after(*r.before, p));
    EXPECT_TRUE(c.equal) << "phase " << p << ": " << c.summary();
  }
}

size_t count_operations(const std::vector<RecordedEdit>& edits, const char* name) {
  return size_t(std::count_if(edits.begin(), edits.end(),
                              [&](const RecordedEdit& e) { return e.what == EditKind::Operation && e.field == name; }));
}

TEST(UpsamplePhases, TheSolutionsFourPhasesBeginWhereItsStepsDo) {
  const std::string text = solution_text();
  const Recording r = record(text, mesh_of(make_cube()));
  ASSERT_TRUE(r.report.identical) << r.report.summary();
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  const size_t E = 18, V = 8, flips = count_operations(r.edits(), "flip");
  ASSERT_GT(flips, 0u);
  ASSERT_EQ(r.edits().size(), E + flips + V + E);
  EXPECT_TRUE(phases.problems.empty()) << phases.problems.front();

  // Phase 1 writes nothing; 2 is the 18 splits, 3 the flips, 4 one position per vertex.
  EXPECT_EQ(phases.span[1].writes, 0u);
  EXPECT_EQ(phases.start_position(UpsamplePhase::Compute), 0u);
  EXPECT_EQ(phases.span[2].first, 0u);
  EXPECT_EQ(phases.span[2].writes, E);
  EXPECT_EQ(phases.span[3].first, E);
  EXPECT_EQ(phases.span[3].writes, flips);
  EXPECT_EQ(phases.span[4].first, E + flips);
  EXPECT_EQ(phases.span[4].writes, V + E);
  EXPECT_EQ(phases.span[4].last, r.edits().size() - 1);
  EXPECT_EQ(r.edits()[phases.span[4].first].where, line_of(text, "v.position = new_position[v.id]"));
  EXPECT_EQ(r.edits()[phases.span[3].first].where, line_of(text, "then mesh:flip(e) end"));

  // Write by write, as the replay counts (write k is edit k - 1).
  EXPECT_EQ(phases.phase_at(0), UpsamplePhase::Compute);
  EXPECT_EQ(phases.phase_at(1), UpsamplePhase::Split);
  EXPECT_EQ(phases.phase_at(E), UpsamplePhase::Split);
  EXPECT_EQ(phases.phase_at(E + 1), UpsamplePhase::Flip);
  EXPECT_EQ(phases.phase_at(E + flips + 1), UpsamplePhase::Commit);
  EXPECT_EQ(phases.phase_at(r.edits().size() + 5), UpsamplePhase::Commit);

  // The boundaries: yours and the core's phases, pointer for pointer and position for position.
  EXPECT_EQ(phases.end_position(UpsamplePhase::Compute), 0u);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Split), E);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Flip), E + flips);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Commit), r.edits().size());
  expect_identical_at_every_boundary(r, phases);

  // Next and previous phase from any write.
  EXPECT_EQ(phases.next_phase_position(0), 1u);
  EXPECT_EQ(phases.next_phase_position(1), E + 1);
  EXPECT_EQ(phases.next_phase_position(E + 3), E + flips + 1);
  EXPECT_EQ(phases.next_phase_position(E + flips + 1), std::nullopt);
  EXPECT_EQ(phases.previous_phase_position(E + flips + 1), E + 1);
  EXPECT_EQ(phases.previous_phase_position(E + 3), E + 1);  // back to the start of the phase it is in
  EXPECT_EQ(phases.previous_phase_position(1), 0u);
  EXPECT_EQ(phases.previous_phase_position(0), std::nullopt);

  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_TRUE(states.refused.empty());
  const MeshCounts cube{8, 18, 12}, split{26, 72, 48};
  const MeshCounts expected[] = {{}, cube, split, split, split};
  for (int p = 1; p <= 4; ++p) {
    const UpsamplePhaseState& s = states.at[size_t(p)];
    EXPECT_TRUE(s.started) << p;
    EXPECT_TRUE(s.identical()) << p << ": " << s.positions_differ << " positions, " << s.halfedges_differ;
    EXPECT_TRUE(s.same_shape) << p;
    EXPECT_EQ(s.mine, expected[p]) << p;
    EXPECT_EQ(s.reference, expected[p]) << p;
  }
}

// The reference split_edge and flip_edge the template offers are recorded as mesh:split and mesh:flip are: the replay
// and the phases are the same whichever a student calls.
TEST(UpsamplePhases, TheReferenceSplitEdgeAndFlipEdgeAreRecordedAsTheMeshMethodsAre) {
  const std::string text =
      replaced(replaced(solution_text(), "mesh:split(e)", "split_edge(mesh, e)"), "mesh:flip(e)", "flip_edge(mesh, e)");
  const Recording r = record(text, mesh_of(make_cube()));
  ASSERT_TRUE(r.report.identical) << r.report.summary();
  const size_t E = 18, V = 8, flips = count_operations(r.edits(), "flip");
  EXPECT_EQ(count_operations(r.edits(), "split"), E);
  ASSERT_EQ(r.edits().size(), E + flips + V + E);
  EXPECT_EQ(r.edits()[0].where, line_of(text, "split_edge(mesh, e)"));
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_TRUE(phases.problems.empty()) << phases.problems.front();
  EXPECT_EQ(phases.span[3].first, E);
  expect_identical_at_every_boundary(r, phases);
}

TEST(UpsamplePhases, FlippingTheHalvesOfSplitEdgesDepartsFromTheReferenceInPhaseThree) {
  const std::string text =
      testing::read_text(testing::source_dir() / "tests/grading/students/upsample_flips_split_halves.lua");
  const Recording r = record(text, mesh_of(make_tetrahedron()));
  ASSERT_FALSE(r.report.equal);
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_TRUE(phases.problems.empty()) << phases.problems.front();
  const size_t E = 6, V = 4, flips = count_operations(r.edits(), "flip");
  EXPECT_EQ(phases.span[2].first, 0u);
  EXPECT_EQ(phases.span[2].writes, E);
  EXPECT_EQ(phases.span[3].first, E);
  EXPECT_EQ(phases.span[3].writes, flips);
  EXPECT_EQ(phases.span[4].first, E + flips);
  EXPECT_EQ(phases.span[4].writes, V + E);

  // Identical to the core's after the splits; different from the flips on.
  const HalfedgeMesh before = *r.before;
  EXPECT_TRUE(compare_meshes_exact(yours_after(r, phases, 2), reference_after(before, 2)).equal);
  EXPECT_FALSE(compare_meshes(yours_after(r, phases, 3), reference_after(before, 3)).equal);
  const UpsamplePhaseStates states = upsample_phase_states(before, r.edits(), phases);
  EXPECT_TRUE(states.at[1].identical());
  EXPECT_TRUE(states.at[2].identical());
  EXPECT_TRUE(states.at[2].same_shape);
  EXPECT_GT(states.at[3].halfedges_differ, 0u);
  EXPECT_EQ(states.at[3].positions_differ, 0u);  // flips move no vertex
  EXPECT_FALSE(states.at[3].same_shape);
  EXPECT_EQ(states.at[3].mine, states.at[3].reference);  // the counts alone do not show it
  EXPECT_FALSE(states.at[4].same_shape);
}

TEST(UpsamplePhases, PositionsMovedWhileStillComputingAreCommittedBeforeTheSplits) {
  // Step 1 moves each vertex at once: its neighbours' sums then read moved positions.
  const std::string text = replaced(solution_text(), "      new_position[v.id] = (1 - n * u) * p + u * sum\n",
                                    "      new_position[v.id] = (1 - n * u) * p + u * sum\n"
                                    "      v.position = new_position[v.id]\n");
  const Recording r = record(text, mesh_of(make_icosahedron()));
  EXPECT_FALSE(r.report.equal);
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_EQ(phases.span[4].first, 0u);
  EXPECT_EQ(phases.span[2].first, 12u);  // after the 12 early moves
  ASSERT_FALSE(phases.problems.empty());
  const std::string early = line_of(text, "      v.position = new_position[v.id]");
  EXPECT_EQ(phases.problems[0], "phase 4 (positions committed) began at write 1 (" + early +
                                    "), before phase 2 (edges split) began at write 13 (" +
                                    line_of(text, "local m = mesh:split(e)") +
                                    "): each step must be done for every element before the next step begins");
  // Phase 1's boundary is the mesh before the first write of any later phase: the input. Phase 4 ends with its last
  // write, phase 2 with the last split.
  EXPECT_EQ(phases.end_position(UpsamplePhase::Compute), 0u);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Split), 12u + 30u);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Commit), r.edits().size());
  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_TRUE(states.at[1].identical());
  // After the splits yours has the 12 original vertices moved, and the 30 new ones at midpoints of moved ones.
  EXPECT_EQ(states.at[2].positions_differ, 12u + 30u);
  EXPECT_EQ(states.at[2].halfedges_differ, 0u);
  EXPECT_TRUE(states.at[2].mine == states.at[2].reference);
}

TEST(UpsamplePhases, FlippingInsideTheSplitLoopInterleavesPhasesTwoAndThree) {
  // After each split, flips the new edges marked so far that join an old and a new vertex, instead of after every
  // split.
  const std::string text = replaced(solution_text(), "    until h == m.halfedge\n",
                                    "    until h == m.halfedge\n"
                                    "    for id in pairs(new_edge) do\n"
                                    "      local f = mesh:edge(id)\n"
                                    "      local x, y = f.halfedge.vertex, f.halfedge.twin.vertex\n"
                                    "      if (is_new[x.id] == true) ~= (is_new[y.id] == true) then mesh:flip(f) end\n"
                                    "    end\n");
  LuaLimits limits;
  limits.wall_seconds = 10;
  const Recording r = record(text, mesh_of(make_cube()), limits);
  ASSERT_TRUE(r.report.mine.error.empty()) << r.report.mine.error;
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  ASSERT_TRUE(phases.span[3].started);
  ASSERT_TRUE(phases.span[4].started);
  EXPECT_GT(phases.span[3].first, 0u);
  EXPECT_LT(phases.span[3].first, phases.span[2].last);
  ASSERT_FALSE(phases.problems.empty());
  const std::string flip_line = line_of(text, "then mesh:flip(f) end");
  EXPECT_EQ(r.edits()[phases.span[3].first].where, flip_line);
  EXPECT_NE(phases.problems[0].find("writes of phase 2 (edges split) come after phase 3 (new edges flipped) began at "
                                    "write " +
                                    std::to_string(phases.span[3].first + 1) + " (" + flip_line + ")"),
            std::string::npos)
      << phases.problems[0];
  // The stepping follows the recording: phase 3 starts inside phase 2, phase 4 after both.
  EXPECT_EQ(phases.next_phase_position(1), phases.span[3].first + 1);
  EXPECT_EQ(phases.next_phase_position(phases.span[3].first + 1), phases.span[4].first + 1);
  EXPECT_EQ(phases.phase_at(phases.span[3].first + 2), phases.phase_of[phases.span[3].first + 1]);
  // Phase 2 is complete after the last split: every edge is split, some new edges are already flipped.
  EXPECT_EQ(phases.end_position(UpsamplePhase::Split), phases.span[2].last + 1);
  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_EQ(states.at[2].mine, states.at[2].reference);
  EXPECT_GT(states.at[2].halfedges_differ, 0u);
}

TEST(UpsamplePhases, ASkippedPhaseNeverStartedAndItsBoundaryIsThePhaseBelow) {
  const std::string text = replaced(solution_text(), "then mesh:flip(e) end", "then end");
  const Recording r = record(text, mesh_of(make_cube()));
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_FALSE(phases.span[3].started);
  EXPECT_EQ(phases.start_position(UpsamplePhase::Flip), std::nullopt);
  ASSERT_EQ(phases.problems.size(), 1u);
  EXPECT_EQ(phases.problems[0], "phase 3 (new edges flipped) never started: no flip was recorded");
  EXPECT_EQ(phases.end_position(UpsamplePhase::Flip), 18u);
  EXPECT_EQ(phases.end_position(UpsamplePhase::Split), 18u);
  EXPECT_EQ(phases.next_phase_position(1), 19u);  // from the splits straight to the commits
  EXPECT_TRUE(compare_meshes_exact(yours_after(r, phases, 3), reference_after(*r.before, 2)).equal);
  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_FALSE(states.at[3].started);
  EXPECT_TRUE(states.at[2].identical());
  EXPECT_GT(states.at[3].halfedges_differ, 0u);
}

TEST(UpsamplePhases, TheTemplateWritesNothingSoOnlyPhaseOneIsThere) {
  const Recording r =
      record(testing::read_text(testing::source_dir() / "scripts/student/upsample.lua"), mesh_of(make_cube()));
  ASSERT_TRUE(r.edits().empty());
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_EQ(phases.phase_at(0), UpsamplePhase::Compute);
  EXPECT_EQ(phases.next_phase_position(0), std::nullopt);
  EXPECT_EQ(phases.previous_phase_position(0), std::nullopt);
  ASSERT_EQ(phases.problems.size(), 3u);
  EXPECT_EQ(phases.problems[0], "phase 2 (edges split) never started: no split was recorded");
  EXPECT_EQ(phases.problems[2], "phase 4 (positions committed) never started: no vertex was moved");
  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_EQ(states.at[4].mine, (MeshCounts{8, 18, 12}));
  EXPECT_EQ(states.at[4].reference, (MeshCounts{26, 72, 48}));
}

// The split and flip solutions of parts 4 and 5 pasted into upsample.lua as local functions: every pointer write is
// recorded on its own and the phases are told apart by what the lines write.
TEST(UpsamplePhases, ASplitAndAFlipWrittenByHandAreToldApart) {
  std::string split = testing::read_text(testing::source_dir() / "tests/exercise/solutions/split.lua");
  std::string flip = testing::read_text(testing::source_dir() / "tests/exercise/solutions/flip.lua");
  split = replaced(replaced(split, "function split_edge(", "local function my_split("),
                   "return { split_edge = split_edge }", "");
  flip = replaced(replaced(flip, "function flip_edge(", "local function my_flip("), "return { flip_edge = flip_edge }",
                  "");
  std::string text = replaced(replaced(solution_text(), "local m = mesh:split(e)", "local m = my_split(mesh, e)"),
                              "then mesh:flip(e) end", "then my_flip(mesh, e) end");
  text = split + flip + text;
  const Recording r = record(text, mesh_of(make_cube()));
  ASSERT_TRUE(r.report.equal) << r.report.summary();
  EXPECT_EQ(count_operations(r.edits(), "split") + count_operations(r.edits(), "flip"), 0u);
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_TRUE(phases.problems.empty()) << phases.problems.front();
  for (size_t i = 0; i < r.edits().size(); ++i) {
    const RecordedEdit& edit = r.edits()[i];
    const int line = std::stoi(edit.where.substr(edit.where.find(':') + 1));
    const int split_lines = int(std::count(split.begin(), split.end(), '\n'));
    const int flip_lines = int(std::count(flip.begin(), flip.end(), '\n'));
    const UpsamplePhase expected = line <= split_lines                ? UpsamplePhase::Split
                                   : line <= split_lines + flip_lines ? UpsamplePhase::Flip
                                                                      : UpsamplePhase::Commit;
    ASSERT_EQ(phases.phase_of[i], expected) << "write " << i + 1 << ": " << describe(edit) << " at " << edit.where;
  }
  expect_identical_at_every_boundary(r, phases);
}

TEST(UpsamplePhases, ARunawayStaysInPhaseTwo) {
  LuaLimits limits;
  limits.instructions = 2'000'000;
  const Recording r =
      record(testing::read_text(testing::source_dir() / "tests/grading/students/upsample_splits_new_edges.lua"),
             mesh_of(make_tetrahedron()), limits);
  ASSERT_FALSE(r.report.mine.error.empty());
  const UpsamplePhases phases = find_upsample_phases(r.edits());
  EXPECT_GT(phases.span[2].writes, 6u);  // more splits than the tetrahedron's 6 edges
  EXPECT_EQ(phases.span[2].writes, r.edits().size());
  ASSERT_EQ(phases.problems.size(), 2u);
  EXPECT_EQ(phases.problems[0], "phase 3 (new edges flipped) never started: no flip was recorded");
  const UpsamplePhaseStates states = upsample_phase_states(*r.before, r.edits(), phases);
  EXPECT_GT(states.at[2].mine.vertices, states.at[2].reference.vertices);
}

TEST(UpsamplePhases, OperationsLoopSubdivisionDoesNotUseAreNamed) {
  std::vector<RecordedEdit> edits(3);
  edits[0].what = EditKind::Operation;
  edits[0].field = "split";
  edits[0].element = EdgeId(0);
  edits[1].what = EditKind::Operation;
  edits[1].field = "collapse";
  edits[1].element = EdgeId(2);
  edits[1].value.element = VertexId(1);
  edits[1].where = "upsample.lua:9";
  edits[2].what = EditKind::Set;
  edits[2].field = "position";
  edits[2].element = VertexId(1);
  const UpsamplePhases phases = find_upsample_phases(edits);
  EXPECT_EQ(phases.phase_of[1], UpsamplePhase::Other);
  EXPECT_EQ(phases.other_writes, 1u);
  EXPECT_EQ(phases.phase_at(2), UpsamplePhase::Other);
  ASSERT_EQ(phases.problems.size(), 2u);
  EXPECT_EQ(phases.problems[1],
            "1 write is not part of Loop subdivision (first: write 2 (upsample.lua:9), collapse e2 -> v1)");
}

}  // namespace
}  // namespace meshedit
