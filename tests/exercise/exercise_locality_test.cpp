// The locality bound of flip_edge and split_edge (exercise_locality.h), through check_exercise as the Exercises tab
// runs it: the correct solutions meet it on the middle edge of an 80x70 grid (11200 triangles); variants of them that
// loop over the mesh or copy all of it are told how many elements they touched, in words and numbers counted at run
// time; the same variants are right on small meshes; a walk around a corner of high degree stays within the bound.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include "core/history.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "exercise/exercise_locality.h"
#include "exercise/exercises.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using Mesh = std::shared_ptr<const HalfedgeMesh>;

Mesh mesh_of(const PolygonMesh& p) { return std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(p)); }

const Mesh& big_grid() {
  static const Mesh grid = mesh_of(make_grid(80, 70));
  return grid;
}

// The grid's diagonal from the vertex at (x, y) to the one at (x + 1, y + 1), as the suites and lesson 4 find it.
EdgeId diagonal_at(const HalfedgeMesh& m, double x, double y) {
  for (EdgeId e : m.edges()) {
    glm::dvec3 p = m.position(m.vertex(m.halfedge(e))), q = m.position(m.vertex(m.twin(m.halfedge(e))));
    if (p.x > q.x) std::swap(p, q);
    if (p.x == x && p.y == y && q.x == x + 1 && q.y == y + 1) return e;
  }
  return {};
}

fs::path solution(const char* file) { return testing::source_dir() / "tests" / "exercise" / "solutions" / file; }

// The solution `file` with `from` replaced by `to` (which must occur), loaded under the same file name.
std::unique_ptr<StudentCode> variant(const char* file, const std::string& from, const std::string& to) {
  std::string text = testing::read_text(solution(file));
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not in " << file << ": " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const fs::path path = testing::scratch_dir() / file;
  std::ofstream(path, std::ios::binary) << text;
  return load_student_file(path);
}

// The solution's first line, and the same line after a loop over the mesh's `what` (every one of them touched).
const std::string kFirstLine = "  local h0 = e.halfedge\n";
std::string after_a_loop_over(const std::string& what) {
  return "  for x in mesh:" + what + "() do end\n" + kFirstLine;
}

// "12 fields of 8 elements": what the core's operation changes of the elements it had, counted from the diff.
std::string changed_fields(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  size_t fields = 0;
  std::set<ElementRef> elements;
  for (const FieldChange& c : diff(before, after)) {
    if (!before.alive(c.element)) continue;
    ++fields;
    elements.insert(c.element);
  }
  return std::to_string(fields) + " fields of " + std::to_string(elements.size()) + " elements";
}

TEST(ExerciseLocality, TheBoundOfAGridDiagonalCountsItsFourCornersOfDegreeSix) {
  const ExerciseInput input = ExerciseInput::edge(big_grid(), diagonal_at(*big_grid(), 40, 35));
  EXPECT_EQ(locality_bound(input), kLocalElements + kPerCornerDegree * 24);
  EXPECT_TRUE(has_locality_bound(Exercise::FlipEdge));
  EXPECT_TRUE(has_locality_bound(Exercise::SplitEdge));
  EXPECT_FALSE(has_locality_bound(Exercise::Upsample));
}

TEST(ExerciseLocality, TheCorrectSolutionsTouchAHandfulOfTheBigGrid) {
  const ExerciseInput input = ExerciseInput::edge(big_grid(), diagonal_at(*big_grid(), 40, 35));
  for (const auto& [exercise, file] : {std::pair{Exercise::FlipEdge, "flip.lua"}, {Exercise::SplitEdge, "split.lua"}}) {
    SCOPED_TRACE(file);
    auto code = load_student_file(solution(file));
    const ExerciseReport report = check_exercise(*code, exercise, input);
    EXPECT_TRUE(report.equal) << report.summary();
    ASSERT_TRUE(report.mine.touched.has_value());
    // Well inside the base bound, as exercise_locality.h reckons a correct solution: 21 to 33 and a walk around c.
    EXPECT_LE(report.mine.touched->elements, kLocalElements) << report.mine.touched->elements;
    EXPECT_GE(report.mine.touched->elements, 10u);
    EXPECT_EQ(report.mine.touched->whole_mesh_call, "");
  }
}

TEST(ExerciseLocality, AFlipThatLoopsOverTheFacesIsToldHowManyItTouched) {
  const EdgeId e = diagonal_at(*big_grid(), 40, 35);
  auto code = variant("flip.lua", kFirstLine, after_a_loop_over("faces"));
  const ExerciseReport report = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(big_grid(), e));
  ASSERT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 1u) << report.summary();  // the mesh it leaves is right
  ASSERT_TRUE(report.mine.touched.has_value());
  const TouchCount& touched = *report.mine.touched;
  // Every face, and the few other elements the flip itself reaches.
  EXPECT_GT(touched.elements, big_grid()->num_faces());
  EXPECT_LT(touched.elements, big_grid()->num_faces() + kLocalElements);
  EXPECT_EQ(touched.whole_mesh_call, "");
  HalfedgeMesh reference = *big_grid();
  ASSERT_TRUE(flip(reference, e).ok());
  EXPECT_EQ(report.differences[0], "your flip_edge touched " + std::to_string(touched.elements) +
                                       " elements of a mesh of 11200 faces (it wrote " +
                                       std::to_string(touched.written) +
                                       " of them and only read the rest); a flip changes a fixed handful (the "
                                       "reference changes " +
                                       changed_fields(*big_grid(), reference) +
                                       "), whatever the mesh's size: walk from e.halfedge instead of looping over "
                                       "the mesh");
}

TEST(ExerciseLocality, ASplitThatCopiesTheWholeMeshIsToldItReadEveryElement) {
  const EdgeId e = diagonal_at(*big_grid(), 40, 35);
  auto code = variant("split.lua", kFirstLine, "  local spare = mesh:copy()\n" + kFirstLine);
  const ExerciseReport report = check_exercise(*code, Exercise::SplitEdge, ExerciseInput::edge(big_grid(), e));
  ASSERT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 1u) << report.summary();
  const HalfedgeMesh& mine = *report.mine.mesh;
  const size_t all = mine.num_vertices() + mine.num_halfedges() + mine.num_edges() + mine.num_faces() + 1;
  HalfedgeMesh reference = *big_grid();
  ASSERT_TRUE(split(reference, e).ok());
  EXPECT_EQ(report.differences[0],
            "your split_edge touched all " + std::to_string(all) +
                " elements of a mesh of 11200 faces: mesh:copy() reads every one; a split changes a fixed handful "
                "(the reference creates 12 elements and changes " +
                changed_fields(*big_grid(), reference) +
                " it had), whatever the mesh's size: walk from e.halfedge instead of reading the whole mesh");
}

TEST(ExerciseLocality, ASmallMeshIsNeverHeldToTheBound) {
  auto flip_code = variant("flip.lua", kFirstLine, after_a_loop_over("halfedges"));
  const Mesh cube = mesh_of(make_cube());
  EXPECT_TRUE(check_exercise(*flip_code, Exercise::FlipEdge, ExerciseInput::edge(cube, EdgeId(0))).equal);
  // 32 x 16 squares: 1024 faces, the smallest mesh held to the bound; 31 x 16 has 992.
  const Mesh held = mesh_of(make_grid(32, 16)), free = mesh_of(make_grid(31, 16));
  EXPECT_FALSE(
      check_exercise(*flip_code, Exercise::FlipEdge, ExerciseInput::edge(held, diagonal_at(*held, 10, 8))).equal);
  EXPECT_TRUE(
      check_exercise(*flip_code, Exercise::FlipEdge, ExerciseInput::edge(free, diagonal_at(*free, 10, 8))).equal);
}

TEST(ExerciseLocality, AWalkAroundACornerOfHighDegreeStaysWithinTheBound) {
  // A fan of 1200 triangles: its centre has degree 1200. A flip of a spoke that walks all the centre's neighbours
  // first (as a check that c and d are not joined may walk c's) is right.
  const Mesh fan = mesh_of(make_fan(1200));
  const std::string from = "  for w in c:neighbors() do\n";
  auto code = variant(
      "flip.lua", from,
      "  for _, v in ipairs({a, b}) do\n    for w in v:neighbors() do local p = w.position end\n  end\n" + from);
  EdgeId spoke;
  for (EdgeId e : fan->edges()) {
    if (!fan->is_boundary(e)) spoke = e;
  }
  const ExerciseReport report = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(fan, spoke));
  EXPECT_TRUE(report.equal) << report.summary();
  ASSERT_TRUE(report.mine.touched.has_value());
  EXPECT_GT(report.mine.touched->elements, 1200u);
}

}  // namespace
}  // namespace meshedit
