// The window and the grader say the same thing. For every buggy fixture in tests/grading/students, the grader's
// output for one failing test carries the diagnosis the window's checker (check_exercise, what the Exercises panel
// runs) gives for the same submission on the same input, and that diagnosis names the mistake. A fixture added to
// the folder without a case here fails EveryBuggyFixtureHasACase.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::grading_dir;
using testing::read_text;
using Mesh = std::shared_ptr<const HalfedgeMesh>;

// The correct fixtures: they have no mistake to name.
const std::set<std::string> kCorrect = {"flip_correct.lua",     "split_correct.lua",
                                        "split_reordered.lua",  "split_without_boundary.lua",
                                        "upsample_correct.lua", "upsample_without_boundary.lua"};

Mesh mesh_of(const PolygonMesh& p) { return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(p)); }

// The suites' own inputs (tests/grading/suites), built the way meshedit.grid, .cube... build them.
Mesh grid(uint32_t nx, uint32_t ny) { return mesh_of(make_grid(nx, ny)); }
// The 80x70 grid of the suites' tests 4.1 and 5.1, and its diagonal from (40, 35) to (41, 36), found by where it is.
ExerciseInput big_grid_diagonal() {
  static const Mesh big = grid(80, 70);
  for (EdgeId e : big->edges()) {
    glm::dvec3 p = big->position(big->vertex(big->halfedge(e)));
    glm::dvec3 q = big->position(big->vertex(big->twin(big->halfedge(e))));
    if (p.x > q.x) std::swap(p, q);
    if (p == glm::dvec3(40, 35, 0) && q == glm::dvec3(41, 36, 0)) return ExerciseInput::edge(big, e);
  }
  return ExerciseInput::edge(big, EdgeId(0));
}
Mesh fan() {  // normals.lua's fan
  PolygonMesh p;
  for (const glm::dvec3& v : {glm::dvec3(0, 0, 0), glm::dvec3(4, 0, 1), glm::dvec3(0, 1, 0.2), glm::dvec3(-1, 0, 0.1),
                              glm::dvec3(0, -3, 2)}) {
    p.add_vertex(v);
  }
  for (const auto& f : std::vector<std::vector<uint32_t>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}}) p.add_face(f);
  return mesh_of(p);
}
BezierPatch sheet() {  // patch.lua's sheet
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = glm::dvec3(c, r, 0.3 * c * c - 0.1 * r + 0.05 * r * c);
  }
  return patch;
}
const std::vector<glm::dvec3> kCubic = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};

struct Case {
  const char* fixture;
  const char* test;                      // the test of the part's suite whose first failing check is `input`
  std::function<ExerciseInput()> input;  // that check's input
  const char* mistake;                   // words that name the mistake
  size_t window_line = 0;                // the window's difference the grader carries (1: the hint under a limit)
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"curve_drops_last.lua", "1.1", [] { return ExerciseInput::curve_step(kCubic, 0.5); },
       "point 3 of the step is missing"},
      {"curve_swapped_weights.lua", "1.2",
       [] {
         return ExerciseInput::curve_step({{0, 0, 0}, {2, 1, 0}}, 0.0);
       },
       "the weights are swapped"},
      {"patch_columns_first.lua", "2.1", [] { return ExerciseInput::patch_point(sheet(), 1, 0); },
       "u and v are swapped"},
      {"normals_unit_average.lua", "3.2", [] { return ExerciseInput::vertex(fan(), VertexId(0)); },
       "is the average of the faces' unit normals; the reference"},
      {"normals_skips_a_face.lua", "3.2", [] { return ExerciseInput::vertex(fan(), VertexId(0)); },
       "leaves out f1, one of the 4 faces around v0; the reference"},
      {"normals_angle_weighted.lua", "3.2", [] { return ExerciseInput::vertex(fan(), VertexId(0)); },
       "weights each face by its angle at v0 (an angle-weighted normal); the reference"},
      {"normals_last_face_only.lua", "3.2", [] { return ExerciseInput::vertex(fan(), VertexId(0)); },
       "is the normal of f1 alone, one of the 4 faces around v0"},
      {"flip_boundary.lua", "4.3", [] { return ExerciseInput::edge(grid(2, 2), EdgeId(0)); },
       "the reference does not flip e0 (e0 is on the boundary"},
      {"flip_breaks_face_cycle.lua", "4.1", [] { return ExerciseInput::edge(grid(1, 1), EdgeId(2)); },
       "h5.next is still h3 after your flip_edge, as before the call; the reference changes it: that pointer breaks "
       "the "
       "face cycle"},
      {"flip_forgets_faces.lua", "4.1", [] { return ExerciseInput::edge(grid(1, 1), EdgeId(2)); },
       "f0.halfedge is h0, but h0.face is f1"},
      {"flip_forgets_vertices.lua", "4.2", [] { return ExerciseInput::edge(mesh_of(make_cube()), EdgeId(0)); },
       "v0.halfedge is h0, but h0 leaves v6"},
      {"flip_scans_the_mesh.lua", "4.1", big_grid_diagonal,
       "elements of a mesh of 11200 faces (it wrote 9 of them and only read the rest); a flip changes a fixed "
       "handful"},
      {"split_scans_the_mesh.lua", "5.1", big_grid_diagonal,
       "elements of a mesh of 11200 faces: mesh:validate() reads every one; a split changes a fixed handful"},
      {"split_corner_average.lua", "5.2", [] { return ExerciseInput::edge(mesh_of(make_cube()), EdgeId(0)); },
       "the average of the corners v0 v2 v3 v6; it belongs at the midpoint of v0 and v2"},
      {"split_wrong_face.lua", "5.1", [] { return ExerciseInput::edge(grid(1, 1), EdgeId(2)); },
       "h12.face is f0, but h12 is in f2's next-cycle"},
      {"upsample_flip_one_check.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "a new edge whose ends were both new was flipped"},
      {"upsample_flips_split_halves.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "an edge that was not new (a half of a split edge) was flipped"},
      {"upsample_integer_division.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "your weight u is 0 for degree 3 (in Lua 3 // 16 is 0, an integer division: write 3 / 16): 4 of the 4 "
       "original vertices kept their old positions"},
      {"upsample_integer_edge_weights.lua", "6.1",
       [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "your edge weights 3/8 and 1/8 are 0 (in Lua 3 // 8 and 1 // 8 are 0, integer divisions: write 3 / 8 and "
       "1 / 8)"},
      {"upsample_marks_by_handle.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "your upsample flipped none of the 4 new edges the reference flips: 4 of your edges still join an original "
       "and a new vertex"},
      {"upsample_one_way_test.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "the old/new test accepts one order only (a old and b new, but not a new and b old"},
      {"upsample_flags_halves.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "your upsample flipped 1 of the 4 new edges the reference flips", 1},
      {"upsample_splits_new_edges.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "upsample did not finish: split only the edges of the original mesh", 1},
      {"upsample_wrong_vertices.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "a position computed for a new vertex (step 2) was written to an original one"},
      {"upsample_wrong_weight.lua", "6.1", [] { return ExerciseInput::whole_mesh(mesh_of(make_tetrahedron())); },
       "moved as if u = 0.125"},
  };
  return all;
}

// "flip_forgets_faces.lua" -> "flip".
std::string part_of(const std::string& fixture) { return fixture.substr(0, fixture.find('_')); }

// What the window's checker says: the fixture saved as its part's file and checked as the Exercises panel checks.
ExerciseReport window_check(const Case& c) {
  const std::string part = part_of(c.fixture);
  const fs::path file = testing::scratch_dir() / (part + ".lua");
  testing::write_text(file, read_text(grading_dir() / "students" / c.fixture));
  LuaLimits limits;
  limits.instructions = 2'000'000;  // for the fixture that never ends
  auto code = load_student_file(file, limits);
  const Exercise exercise = *find_exercise(part);
  return check_exercise(*code, exercise, c.input());
}

// What the grader says: the output of the case's test in the part's suite.
std::string grader_output(const Case& c) {
  const std::string part = part_of(c.fixture);
  auto suite = Suite::load(grading_dir() / "suites" / (part + ".lua"));
  GradeOptions options = testing::quick_options();
  options.time_limit_cap = 0.5;
  const GradeReport report = grade(
      *suite, testing::submission_of({{part + ".lua", read_text(grading_dir() / "students" / c.fixture)}}), options);
  for (const TestResult& t : report.tests) {
    if (t.number == c.test) return t.output;
  }
  return "(no test " + std::string(c.test) + ")";
}

class WindowAndGrader : public ::testing::TestWithParam<Case> {};

TEST_P(WindowAndGrader, TheGraderCarriesTheWindowsDiagnosis) {
  const Case& c = GetParam();
  const ExerciseReport window = window_check(c);
  ASSERT_FALSE(window.equal) << c.fixture;
  ASSERT_GT(window.differences.size(), c.window_line) << window.summary();
  const std::string& diagnosis = window.differences[c.window_line];
  EXPECT_NE(diagnosis.find(c.mistake), std::string::npos) << "the window does not name the mistake: " << diagnosis;
  const std::string grader = grader_output(c);
  EXPECT_NE(grader.find(diagnosis), std::string::npos) << "window: " << diagnosis << "\ngrader: " << grader;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, WindowAndGrader, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& fixture) {
                           std::string name = fixture.param.fixture;
                           name = name.substr(0, name.size() - 4);
                           return name;
                         });

// The course's rule (a vertex's halfedge may be any halfedge leaving it) in both: a split that points the new
// boundary vertex at its interior halfedge is right in the window, with a note, and scores the boundary test.
TEST(WindowAndGrader, ABoundaryVertexMayPointAtAnInteriorHalfedgeInBoth) {
  std::string text = read_text(grading_dir() / "students" / "split_correct.lua");
  const std::string from = "  m.halfedge = n1\n";  // n1 runs m -> a: on the boundary loop when the edge is
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "  m.halfedge = h0\n");  // h0 runs m -> b, inside f0
  const fs::path file = testing::scratch_dir() / "split.lua";
  testing::write_text(file, text);
  auto code = load_student_file(file);
  const ExerciseReport window = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(grid(2, 2), EdgeId(0)));
  EXPECT_TRUE(window.equal) << window.summary();
  ASSERT_FALSE(window.notes.empty());
  EXPECT_NE(window.notes.back().find("is not on the boundary loop: accepted (the course lets a vertex's halfedge be "
                                     "any halfedge leaving it"),
            std::string::npos)
      << window.notes.back();
  auto suite = Suite::load(grading_dir() / "suites" / "split.lua");
  const GradeReport report = grade(*suite, testing::submission_of({{"split.lua", text}}), testing::quick_options());
  EXPECT_EQ(report.score, 10.0);  // every base point and the boundary extra credit
  EXPECT_EQ(report.failed(), 0u);
}

// The boundary rules are extra credit: an upsample with the interior rules only is right on closed meshes, and on the
// grid of test 6.4 the window and the grader both name the interior rules used on the boundary.
TEST(WindowAndGrader, TheExtraCreditBoundaryRulesAreNamedAlikeInBoth) {
  const Case c{"upsample_without_boundary.lua", "6.4", [] { return ExerciseInput::whole_mesh(grid(2, 2)); }, ""};
  const ExerciseReport window = window_check(c);
  ASSERT_FALSE(window.equal);
  const auto names = [&](const std::string& words) {
    for (const std::string& d : window.differences) {
      if (d.find(words) != std::string::npos) return d;
    }
    return std::string();
  };
  const std::string vertex = names(
      "boundary vertices, e.g. v0 (3 neighbours, 2 of them along the boundary), moved by "
      "the interior rule");
  const std::string edge = names("are at the interior rule 3/8 (a + b) + 1/8 (c + d) with d read across the boundary");
  ASSERT_NE(vertex, "") << window.summary();
  ASSERT_NE(edge, "") << window.summary();
  const std::string grader = grader_output(c);
  EXPECT_NE(grader.find(vertex), std::string::npos) << grader;
  EXPECT_NE(grader.find(edge), std::string::npos) << grader;
}

TEST(WindowAndGrader, EveryBuggyFixtureHasACase) {
  std::set<std::string> covered;
  for (const Case& c : cases()) covered.insert(c.fixture);
  size_t buggy = 0;
  for (const auto& entry : fs::directory_iterator(grading_dir() / "students")) {
    const std::string name = entry.path().filename().string();
    if (kCorrect.count(name)) continue;
    ++buggy;
    EXPECT_TRUE(covered.count(name)) << name << " is a buggy fixture with no case in this test";
  }
  EXPECT_EQ(buggy, cases().size());
}

}  // namespace
}  // namespace meshedit
