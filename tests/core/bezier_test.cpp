// Bézier curves, patches and patch tessellation: exact de Casteljau pyramids, the row-then-column patch
// order, welding ids, and the project's teapot asset building into a half-edge mesh.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                                  kNaN, kInf, the Bernstein forms (bernstein_curve, bernstein_patch),
//                                            grid_patch, lopsided_patch, expect_near, outgoing_count, read_bez
//   curves                                   de Casteljau levels and steps in 2D and 3D (hand-worked pyramid, Bernstein
//                                            form, endpoints, non-finite input), split_curve
//   patches                                  evaluate_patch and its steps: rows at u then the column at v, the
//                                            Bernstein sum, corners, exact bilinear points
//   tessellation: one patch                  a flat patch's documented grid, ids and triangles; the default resolution
//   tessellation: welding                    shared edges welded (within the tolerance, parametrised backwards),
//                                            collapsed rows around an apex, surfaces touching at a point or oppositely
//                                            oriented cut apart
//   tessellation: hostile input              non-finite or huge coordinates, a patch that is one point, bad resolutions
//   the shipped assets and the course files  teapot.bez at every resolution, the curve assets, the course's .bez files
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/bezier.h"
#include "core/halfedge_mesh.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/patch_tessellation.h"
#include "core/validate.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

using glm::dvec2;
using glm::dvec3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

double bernstein(int n, int i, double t) { return binomial(n, i) * std::pow(t, i) * std::pow(1.0 - t, n - i); }

template <class P>
P bernstein_curve(const std::vector<P>& points, double t) {
  const int n = static_cast<int>(points.size()) - 1;
  P sum(0.0);
  for (int i = 0; i <= n; ++i) sum += bernstein(n, i, t) * points[i];
  return sum;
}

dvec3 bernstein_patch(const BezierPatch& patch, double u, double v) {
  dvec3 sum(0.0);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) sum += bernstein(3, r, v) * bernstein(3, c, u) * patch.at(r, c);
  }
  return sum;
}

// at(r, c) = origin + c * du + r * dv, so P(u, v) = origin + 3u du + 3v dv exactly (linear precision).
BezierPatch grid_patch(dvec3 origin, dvec3 du, dvec3 dv) {
  BezierPatch p;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) p.at(r, c) = origin + double(c) * du + double(r) * dv;
  }
  return p;
}

// A patch with no symmetry between rows and columns, so evaluating in the wrong order shows.
BezierPatch lopsided_patch() {
  BezierPatch p;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) p.at(r, c) = dvec3(c + 0.5 * r * r, 2.0 * r - c * c, double(r * c % 3) - 0.25 * c);
  }
  return p;
}

void expect_near(dvec3 a, dvec3 b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
void expect_near(dvec2 a, dvec2 b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
}

uint32_t outgoing_count(const HalfedgeMesh& m, VertexId v) {
  uint32_t count = 0;
  for (HalfedgeId h : m.halfedges()) count += m.vertex(h) == v ? 1 : 0;
  return count;
}

// A few lines standing in for the .bez reader (engine/io): count, then 16 "x y z" per patch.
std::vector<BezierPatch> read_bez(const std::filesystem::path& path) {
  std::ifstream in(path);
  size_t count = 0;
  in >> count;
  std::vector<BezierPatch> patches(count);
  for (BezierPatch& p : patches) {
    for (dvec3& q : p.points) in >> q.x >> q.y >> q.z;
  }
  EXPECT_FALSE(in.fail()) << path;
  std::string rest;
  in >> rest;
  EXPECT_TRUE(rest.empty()) << path << " has trailing text";
  return patches;
}

// ---- curves ----------------------------------------------------------------------------------------

// P = (0,0) (4,8) (8,0) (12,8) at t = 1/4, each step 3/4 a + 1/4 b, worked by hand:
//   level 1: (1,2) (5,6) (9,2);  level 2: (2,3) (6,5);  level 3: (3, 3.5)
// (Bernstein check: x = (4*27 + 8*9 + 12)/64 = 3, y = (8*27 + 8)/64 = 3.5.)
const std::vector<dvec2> kCubic = {{0, 0}, {4, 8}, {8, 0}, {12, 8}};

TEST(DeCasteljau, CubicPyramidAtAQuarterIsExact) {
  const auto levels = de_casteljau_levels(kCubic, 0.25);
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_EQ(levels[0], kCubic);
  EXPECT_EQ(levels[1], (std::vector<dvec2>{{1, 2}, {5, 6}, {9, 2}}));
  EXPECT_EQ(levels[2], (std::vector<dvec2>{{2, 3}, {6, 5}}));
  EXPECT_EQ(levels[3], (std::vector<dvec2>{{3, 3.5}}));
  EXPECT_EQ(de_casteljau_step(kCubic, 0.25), levels[1]);
  EXPECT_EQ(de_casteljau_step(levels[1], 0.25), levels[2]);
  EXPECT_EQ(evaluate_curve(kCubic, 0.25), dvec2(3, 3.5));
  EXPECT_EQ(evaluate_curve(BezierCurve{kCubic}, 0.25), dvec2(3, 3.5));
}

TEST(DeCasteljau, SameStepsIn3D) {
  const std::vector<dvec3> cubic = {{0, 0, 1}, {4, 8, 1}, {8, 0, 1}, {12, 8, 1}};
  const auto levels = de_casteljau_levels(cubic, 0.25);
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_EQ(levels[1], (std::vector<dvec3>{{1, 2, 1}, {5, 6, 1}, {9, 2, 1}}));
  EXPECT_EQ(levels[2], (std::vector<dvec3>{{2, 3, 1}, {6, 5, 1}}));
  EXPECT_EQ(levels[3], (std::vector<dvec3>{{3, 3.5, 1}}));
  EXPECT_EQ(evaluate_curve(cubic, 0.25), dvec3(3, 3.5, 1));
}

TEST(DeCasteljau, EmptyAndSinglePointInput) {
  const std::vector<dvec2> none;
  const std::vector<dvec2> one = {{0.3, 0.7}};
  EXPECT_TRUE(de_casteljau_step(none, 0.5).empty());
  EXPECT_TRUE(de_casteljau_step(one, 0.5).empty());
  EXPECT_TRUE(de_casteljau_levels(none, 0.5).empty());
  EXPECT_EQ(de_casteljau_levels(one, 0.5), (std::vector<std::vector<dvec2>>{one}));
  EXPECT_EQ(evaluate_curve(one, 0.9), dvec2(0.3, 0.7));
  const dvec2 nowhere = evaluate_curve(none, 0.5);
  EXPECT_TRUE(std::isnan(nowhere.x) && std::isnan(nowhere.y));
  const auto halves = split_curve(none, 0.5);
  EXPECT_TRUE(halves.left.empty() && halves.right.empty());
  EXPECT_TRUE(de_casteljau_step(std::vector<dvec3>{}, 0.5).empty());
  EXPECT_TRUE(std::isnan(evaluate_curve(std::vector<dvec3>{}, 0.5).z));
}

TEST(DeCasteljau, EndpointsInterpolate) {
  const std::vector<dvec2> quartic = {{0.15, 0.15}, {0.9, 0.25}, {0.7, 0.95}, {0.2, 0.7}, {0.6, 0.35}};
  EXPECT_EQ(evaluate_curve(quartic, 0.0), quartic.front());
  EXPECT_EQ(evaluate_curve(quartic, 1.0), quartic.back());
  const std::vector<dvec3> cubic = {{0.1, -2, 3}, {7, 0.3, -1}, {2, 2, 2}, {-0.7, 5, 0.01}};
  EXPECT_EQ(evaluate_curve(cubic, 0.0), cubic.front());
  EXPECT_EQ(evaluate_curve(cubic, 1.0), cubic.back());
}

TEST(DeCasteljau, LinearCurveIsTheLerp) {
  const std::vector<dvec2> line = {{1, 2}, {5, -2}};
  EXPECT_EQ(evaluate_curve(line, 0.25), dvec2(2, 1));
  EXPECT_EQ(evaluate_curve(line, 0.5), dvec2(3, 0));
  EXPECT_EQ(evaluate_curve(line, 2.0), dvec2(9, -6));  // extrapolates the same line
  for (double t : {0.1, 0.3, 0.77}) expect_near(evaluate_curve(line, t), dvec2(1 + 4 * t, 2 - 4 * t), 1e-15);
}

TEST(DeCasteljau, MatchesTheBernsteinForm) {
  std::mt19937 rng(184);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  for (size_t n : {2u, 3u, 4u, 5u, 8u}) {
    std::vector<dvec2> p2(n);
    std::vector<dvec3> p3(n);
    for (auto& p : p2) p = dvec2(coord(rng), coord(rng));
    for (auto& p : p3) p = dvec3(coord(rng), coord(rng), coord(rng));
    for (int k = 0; k <= 20; ++k) {
      const double t = k / 20.0;
      expect_near(evaluate_curve(p2, t), bernstein_curve(p2, t), 1e-13);
      expect_near(evaluate_curve(p3, t), bernstein_curve(p3, t), 1e-13);
    }
  }
}

TEST(SplitCurve, HalvesAreTheCurveReparametrised) {
  const std::vector<dvec2> quartic = {{0.15, 0.15}, {0.9, 0.25}, {0.7, 0.95}, {0.2, 0.7}, {0.6, 0.35}};
  for (double t : {0.25, 0.4, 0.5, 0.9}) {
    const auto halves = split_curve(quartic, t);
    ASSERT_EQ(halves.left.size(), 5u);
    ASSERT_EQ(halves.right.size(), 5u);
    const dvec2 at_t = evaluate_curve(quartic, t);
    EXPECT_EQ(halves.left.front(), quartic.front());
    EXPECT_EQ(halves.right.back(), quartic.back());
    EXPECT_EQ(halves.left.back(), at_t);
    EXPECT_EQ(halves.right.front(), at_t);
    for (int k = 0; k <= 10; ++k) {
      const double s = k / 10.0;
      expect_near(evaluate_curve(halves.left, s), evaluate_curve(quartic, t * s), 1e-14);
      expect_near(evaluate_curve(halves.right, s), evaluate_curve(quartic, t + (1 - t) * s), 1e-14);
    }
  }
}

TEST(SplitCurve, CubicHalvesHaveHandComputedPoints) {
  // The pyramid of CubicPyramidAtAQuarterIsExact read down its left and right edges.
  const auto halves = split_curve(kCubic, 0.25);
  EXPECT_EQ(halves.left, (std::vector<dvec2>{{0, 0}, {1, 2}, {2, 3}, {3, 3.5}}));
  EXPECT_EQ(halves.right, (std::vector<dvec2>{{3, 3.5}, {6, 5}, {9, 2}, {12, 8}}));
  const std::vector<dvec3> cubic3 = {{0, 0, 0}, {4, 8, 4}, {8, 0, 8}, {12, 8, 12}};
  const auto halves3 = split_curve(cubic3, 0.25);
  EXPECT_EQ(halves3.right, (std::vector<dvec3>{{3, 3.5, 3}, {6, 5, 6}, {9, 2, 9}, {12, 8, 12}}));
}

TEST(DeCasteljau, NonFiniteInputDoesNotCrash) {
  const std::vector<dvec2> with_nan = {{0, 0}, {kNaN, 1}, {2, kInf}};
  const dvec2 p = evaluate_curve(with_nan, 0.5);
  EXPECT_TRUE(std::isnan(p.x));
  EXPECT_FALSE(std::isfinite(p.y));
  EXPECT_TRUE(std::isnan(evaluate_curve(kCubic, kNaN).x));
  EXPECT_EQ(de_casteljau_levels(kCubic, kInf).size(), 4u);
  EXPECT_EQ(split_curve(with_nan, kNaN).left.size(), 3u);
}

// ---- patches ---------------------------------------------------------------------------------------

TEST(BezierPatchEval, RowsAtUFirstThenTheColumnAtV) {
  const BezierPatch patch = lopsided_patch();
  const double u = 0.3, v = 0.65;
  const PatchEvaluation steps = evaluate_patch_steps(patch, u, v);
  for (int r = 0; r < 4; ++r) {
    const std::vector<dvec3> row = {patch.at(r, 0), patch.at(r, 1), patch.at(r, 2), patch.at(r, 3)};
    EXPECT_EQ(steps.row_points[r], evaluate_curve(row, u)) << "row " << r;
    expect_near(steps.row_points[r], bernstein_curve(row, u), 1e-13);
  }
  // Had the columns been evaluated first (at u), the intermediate points would differ.
  const std::vector<dvec3> column0 = {patch.at(0, 0), patch.at(1, 0), patch.at(2, 0), patch.at(3, 0)};
  EXPECT_GT(glm::length(steps.row_points[0] - evaluate_curve(column0, u)), 0.1);

  ASSERT_EQ(steps.column_levels.size(), 4u);
  EXPECT_EQ(steps.column_levels[0], std::vector<dvec3>(steps.row_points.begin(), steps.row_points.end()));
  EXPECT_EQ(steps.column_levels[1].size(), 3u);
  EXPECT_EQ(steps.column_levels[2].size(), 2u);
  ASSERT_EQ(steps.column_levels[3].size(), 1u);
  EXPECT_EQ(steps.column_levels[3][0], steps.point);
  EXPECT_EQ(steps.column_levels, de_casteljau_levels(steps.column_levels[0], v));
  EXPECT_EQ(evaluate_patch(patch, u, v), steps.point);
}

TEST(BezierPatchEval, EqualsTheDoubleBernsteinSumAndColumnsFirst) {
  const BezierPatch patch = lopsided_patch();
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const double u = i / 8.0, v = j / 8.0;
      const dvec3 p = evaluate_patch(patch, u, v);
      expect_near(p, bernstein_patch(patch, u, v), 1e-12);
      // The other order, columns at v then the resulting row at u: the same tensor-product surface.
      std::vector<dvec3> row_of_columns;
      for (int c = 0; c < 4; ++c) {
        row_of_columns.push_back(
            evaluate_curve(std::vector<dvec3>{patch.at(0, c), patch.at(1, c), patch.at(2, c), patch.at(3, c)}, v));
      }
      expect_near(p, evaluate_curve(row_of_columns, u), 1e-12);
    }
  }
}

TEST(BezierPatchEval, CornersAreControlPoints) {
  const BezierPatch patch = lopsided_patch();
  EXPECT_EQ(evaluate_patch(patch, 0, 0), patch.at(0, 0));
  EXPECT_EQ(evaluate_patch(patch, 1, 0), patch.at(0, 3));
  EXPECT_EQ(evaluate_patch(patch, 0, 1), patch.at(3, 0));
  EXPECT_EQ(evaluate_patch(patch, 1, 1), patch.at(3, 3));
}

TEST(BezierPatchEval, BilinearPatchHasExactPoints) {
  // at(r, c) = (c, 2r, r c): P(u, v) = (3u, 6v, 9uv).
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = dvec3(c, 2 * r, r * c);
  }
  EXPECT_EQ(evaluate_patch(patch, 0.25, 0.5), dvec3(0.75, 3, 1.125));
  EXPECT_EQ(evaluate_patch(patch, 0.5, 0.75), dvec3(1.5, 4.5, 3.375));
  EXPECT_EQ(evaluate_patch(patch, 0.5, 0.5), dvec3(1.5, 3, 2.25));
  const PatchEvaluation steps = evaluate_patch_steps(patch, 0.25, 0.5);
  EXPECT_EQ(steps.row_points,
            (std::array<dvec3, 4>{dvec3(0.75, 0, 0), dvec3(0.75, 2, 0.75), dvec3(0.75, 4, 1.5), dvec3(0.75, 6, 2.25)}));
  EXPECT_EQ(steps.column_levels[1], (std::vector<dvec3>{{0.75, 1, 0.375}, {0.75, 3, 1.125}, {0.75, 5, 1.875}}));
}

TEST(BezierPatchEval, NonFiniteInputDoesNotCrash) {
  BezierPatch patch = lopsided_patch();
  patch.at(1, 2).x = kNaN;
  EXPECT_TRUE(std::isnan(evaluate_patch(patch, 0.5, 0.5).x));
  EXPECT_TRUE(std::isnan(evaluate_patch(lopsided_patch(), kNaN, 0.5).y));
  EXPECT_EQ(evaluate_patch_steps(lopsided_patch(), 0.5, kInf).column_levels.size(), 4u);
}

// ---- tessellation: one patch -----------------------------------------------------------------------

TEST(PatchTessellation, OneFlatPatchGivesTheDocumentedGrid) {
  const uint32_t n = 4;
  const BezierPatch patch = grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0});  // P(u, v) = (3u, 6v, 0)
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(std::span(&patch, 1), n, &report);
  ASSERT_EQ(mesh.num_vertices(), (n + 1) * (n + 1));
  ASSERT_EQ(mesh.num_faces(), 2 * n * n);
  EXPECT_EQ(report.samples, 25u);
  EXPECT_EQ(report.welded_vertices, 25u);
  EXPECT_EQ(report.degenerate_triangles, 0u);
  EXPECT_EQ(report.vertex_splits, 0u);
  EXPECT_EQ(mesh.positions[0], patch.at(0, 0));
  EXPECT_EQ(mesh.positions[n], patch.at(0, 3));
  EXPECT_EQ(mesh.positions[n * (n + 1)], patch.at(3, 0));
  EXPECT_EQ(mesh.positions[(n + 1) * (n + 1) - 1], patch.at(3, 3));
  for (uint32_t j = 0; j <= n; ++j) {
    for (uint32_t i = 0; i <= n; ++i) EXPECT_EQ(mesh.positions[j * (n + 1) + i], dvec3(0.75 * i, 1.5 * j, 0));
  }
  // Cell (i, j) = (1, 2): a = v11, b = v12, c = v17, d = v16.
  const uint32_t cell = 2 * n + 1;
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(2 * cell).begin(), mesh.face(2 * cell).end()),
            (std::vector<uint32_t>{11, 12, 17}));
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(2 * cell + 1).begin(), mesh.face(2 * cell + 1).end()),
            (std::vector<uint32_t>{11, 17, 16}));
  // Normals point along dP/du x dP/dv = +z.
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const auto t = mesh.face(f);
    const dvec3 normal =
        glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    EXPECT_GT(normal.z, 0.0) << "face " << f;
  }
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.degree(FaceId::boundary(0)), 4 * n);
}

TEST(PatchTessellation, DefaultResolutionIsSixteen) {
  const BezierPatch patch = lopsided_patch();
  const PolygonMesh mesh = tessellate_patches(std::span(&patch, 1));
  EXPECT_EQ(mesh.num_vertices(), 17u * 17u);
  EXPECT_EQ(mesh.num_faces(), 2u * 16u * 16u);
  EXPECT_EQ(mesh.positions[17 * 5 + 3], evaluate_patch(patch, 3 / 16.0, 5 / 16.0));
}

// ---- tessellation: welding -------------------------------------------------------------------------

TEST(PatchTessellation, SharedEdgeIsWeldedAndBuilds) {
  const uint32_t n = 2;
  // A over x in [0, 3], B over x in [3, 6]; B's first column is A's last.
  const std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                              grid_patch({3, 0, 0}, {1, 0, 0}, {0, 2, 0})};
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, n, &report);
  ASSERT_EQ(mesh.num_vertices(), 2 * (n + 1) * (n + 1) - (n + 1));
  EXPECT_EQ(mesh.num_faces(), 4 * n * n);
  EXPECT_EQ(report.vertex_splits, 0u);
  // B's samples (0, j) are A's vertices (2, j) = v2, v5, v8; its own start at v9:
  // row j = 0 gives v9 v10, row j = 1 gives v11 v12. B's cell (0, 0) is (v2 v9 v11) then (v2 v11 v5).
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(2 * n * n).begin(), mesh.face(2 * n * n).end()),
            (std::vector<uint32_t>{2, 9, 11}));
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(2 * n * n + 1).begin(), mesh.face(2 * n * n + 1).end()),
            (std::vector<uint32_t>{2, 11, 5}));
  EXPECT_EQ(mesh.positions[9], dvec3(4.5, 0, 0));
  EXPECT_EQ(mesh.positions[11], dvec3(4.5, 3, 0));

  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.degree(FaceId::boundary(0)), 6 * n);  // a 2n by n rectangle of grid steps
  EXPECT_FALSE(m.is_boundary(VertexId(5)));         // A's (2, 1): inside once B is welded on
  EXPECT_TRUE(m.is_boundary(VertexId(2)));
  EXPECT_TRUE(m.is_boundary(VertexId(10)));
}

TEST(PatchTessellation, WeldsWithinTheRelativeTolerance) {
  // B's shared column moved by 1e-12 (well under 1e-9 of the 8.5 diagonal) still welds; 1e-6 does not.
  for (const auto& [offset, welded] : {std::pair{1e-12, true}, std::pair{1e-6, false}}) {
    std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                          grid_patch({3, 0, 0}, {1, 0, 0}, {0, 2, 0})};
    for (int r = 0; r < 4; ++r) patches[1].at(r, 0).x += offset;
    const PolygonMesh mesh = tessellate_patches(patches, 2);
    EXPECT_EQ(mesh.num_vertices(), welded ? 15u : 18u) << offset;
    const HalfedgeMesh m = build_halfedge_mesh(mesh);
    EXPECT_EQ(m.num_boundaries(), welded ? 1u : 2u) << offset;
  }
}

TEST(PatchTessellation, SharedEdgeParametrisedBackwardsIsWelded) {
  // B is turned half a turn in (u, v): its u runs -x and its v runs -y (still normal +z), so the shared
  // edge x = 3 is A's u = 1 going up and B's u = 1 going down; the samples meet at v and 1 - v.
  const uint32_t n = 5;
  const std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                              grid_patch({6, 6, 0}, {-1, 0, 0}, {0, -2, 0})};
  const PolygonMesh mesh = tessellate_patches(patches, n);
  EXPECT_EQ(mesh.num_vertices(), 2 * (n + 1) * (n + 1) - (n + 1));
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.degree(FaceId::boundary(0)), 6 * n);
}

TEST(PatchTessellation, CollapsedRowDropsDegenerateTrianglesAndBuilds) {
  // Row 0 collapsed to the origin, like the teapot's lid top: a flat triangle-shaped patch.
  const uint32_t n = 4;
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = dvec3(r * (c - 1.5), 2.0 * r, 0);
  }
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(std::span(&patch, 1), n, &report);
  EXPECT_EQ(report.degenerate_triangles, n);  // (a b c) of every cell in row j = 0
  EXPECT_EQ(report.welded_vertices, (n + 1) * (n + 1) - n);
  ASSERT_EQ(mesh.num_vertices(), (n + 1) * (n + 1) - n);
  ASSERT_EQ(mesh.num_faces(), 2 * n * n - n);
  EXPECT_EQ(mesh.positions[0], dvec3(0, 0, 0));
  // Cell (0, 0) keeps only (a c d) = (apex, sample (1,1) = v2, sample (0,1) = v1).
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(0).begin(), mesh.face(0).end()), (std::vector<uint32_t>{0, 2, 1}));
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const auto t = mesh.face(f);
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "face " << f;
  }
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.degree(FaceId::boundary(0)), 3 * n);   // the collapsed side has no length
  EXPECT_EQ(outgoing_count(m, VertexId(0)), n + 1);  // n triangles fan around the apex, plus the boundary
}

TEST(PatchTessellation, FourCollapsedPatchesCloseAroundTheApex) {
  // Four quarter-cones, each with row 0 at the apex, meeting edge to edge like the teapot's lid top.
  std::array<BezierPatch, 4> patches;
  for (int q = 0; q < 4; ++q) {
    const double a0 = q * std::numbers::pi / 2;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        const double a = a0 - c * std::numbers::pi / 6;  // u turns clockwise seen from +z; v runs outwards and down
        patches[q].at(r, c) = dvec3(r * std::cos(a), r * std::sin(a), -0.5 * r);
      }
    }
    patches[q].at(0, 0) = patches[q].at(0, 1) = patches[q].at(0, 2) = patches[q].at(0, 3) = dvec3(0, 0, 0);
  }
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, 6, &report);
  EXPECT_EQ(report.degenerate_triangles, 4u * 6u);
  EXPECT_EQ(report.vertex_splits, 0u);
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_FALSE(m.is_boundary(VertexId(0)));
  EXPECT_EQ(outgoing_count(m, VertexId(0)), 24u);
  EXPECT_EQ(m.num_boundaries(), 1u);
}

TEST(PatchTessellation, SurfacesTouchingAtAPointAreKeptApart) {
  // A over [0,3]x[0,6] and B over [3,6]x[6,12] share only the point (3, 6, 0): A's v15 (n = 3).
  const uint32_t n = 3;
  const std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                              grid_patch({3, 6, 0}, {1, 0, 0}, {0, 2, 0})};
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, n, &report);
  EXPECT_EQ(report.welded_vertices, 31u);
  EXPECT_EQ(report.vertex_splits, 1u);
  ASSERT_EQ(mesh.num_vertices(), 32u);
  EXPECT_EQ(mesh.positions[15], dvec3(3, 6, 0));
  EXPECT_EQ(mesh.positions[31], dvec3(3, 6, 0));  // B's copy, appended last
  // A keeps v15 (its fan holds the lowest triangle); B's first triangle uses the copy.
  EXPECT_EQ(std::vector<uint32_t>(mesh.face(2 * n * n).begin(), mesh.face(2 * n * n).end()),
            (std::vector<uint32_t>{31, 16, 20}));
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_EQ(m.num_boundaries(), 2u);
}

TEST(PatchTessellation, OppositelyOrientedNeighbourIsCutFree) {
  // B's columns reversed: its normal is -z, so the shared edge would be used twice in one direction.
  const uint32_t n = 3;
  const std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                              grid_patch({6, 0, 0}, {-1, 0, 0}, {0, 2, 0})};
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, n, &report);
  EXPECT_EQ(report.welded_vertices, 2 * (n + 1) * (n + 1) - (n + 1));
  EXPECT_EQ(report.vertex_splits, n + 1);  // every vertex of the shared edge
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_EQ(m.num_boundaries(), 2u);
}

// ---- tessellation: hostile input -------------------------------------------------------------------

TEST(PatchTessellation, NonFiniteControlPointsDoNotThrow) {
  std::array<BezierPatch, 2> patches = {grid_patch({0, 0, 0}, {1, 0, 0}, {0, 2, 0}),
                                        grid_patch({3, 0, 0}, {1, 0, 0}, {0, 2, 0})};
  patches[1].at(2, 2).y = kNaN;
  patches[1].at(3, 3).z = kInf;
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, 4, &report);
  EXPECT_EQ(mesh.num_faces(), 64u);
  EXPECT_EQ(report.samples, 50u);
  EXPECT_EQ(mesh.positions[0], dvec3(0, 0, 0));  // A is unaffected
  std::array<BezierPatch, 1> all_nan;
  for (dvec3& p : all_nan[0].points) p = dvec3(kNaN);
  const PolygonMesh nan_mesh = tessellate_patches(all_nan, 2);
  EXPECT_EQ(nan_mesh.num_vertices(), 9u);  // NaN samples never weld
  EXPECT_EQ(nan_mesh.num_faces(), 8u);
}

TEST(PatchTessellation, CoordinatesNearTheDoubleLimitDoNotBreakTheHash) {
  // The bounding box's diagonal overflows to infinity: welding falls back to exact matches.
  std::array<BezierPatch, 2> patches = {grid_patch({-1e308, 0, 0}, {0, 1, 0}, {0, 0, 1}),
                                        grid_patch({1e308, 0, 0}, {0, 1, 0}, {0, 0, 1})};
  const PolygonMesh mesh = tessellate_patches(patches, 2);
  EXPECT_EQ(mesh.num_vertices(), 18u);
  EXPECT_EQ(mesh.num_faces(), 16u);
  EXPECT_EQ(mesh.positions[9], dvec3(1e308, 0, 0));
  EXPECT_EQ(build_halfedge_mesh(mesh).num_boundaries(), 2u);
}

TEST(PatchTessellation, PatchCollapsedToAPointLeavesNoTriangles) {
  std::array<BezierPatch, 1> point;
  for (dvec3& p : point[0].points) p = dvec3(1, 2, 3);
  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(point, 3, &report);
  EXPECT_EQ(mesh.num_vertices(), 1u);
  EXPECT_EQ(mesh.num_faces(), 0u);
  EXPECT_EQ(report.degenerate_triangles, 18u);
  EXPECT_EQ(tessellate_patches(std::span<const BezierPatch>(), 16).num_vertices(), 0u);
}

TEST(PatchTessellation, ResolutionOutOfRangeIsRefused) {
  const BezierPatch patch = lopsided_patch();
  EXPECT_THROW(tessellate_patches(std::span(&patch, 1), 0), MeshError);
  EXPECT_THROW(tessellate_patches(std::span(&patch, 1), -3), MeshError);
  EXPECT_THROW(tessellate_patches(std::span(&patch, 1), kMaxPatchResolution + 1), MeshError);
  EXPECT_EQ(tessellate_patches(std::span(&patch, 1), 1).num_faces(), 2u);
}

// ---- the shipped assets and the course files -------------------------------------------------------

TEST(TeapotAsset, HasThirtyTwoFinitePatchesAndBuilds) {
  const auto patches = read_bez(testing::source_dir() / "assets" / "teapot.bez");
  ASSERT_EQ(patches.size(), 32u);
  for (size_t p = 0; p < patches.size(); ++p) {
    for (const dvec3& q : patches[p].points) {
      EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)) << "patch " << p;
    }
  }
  EXPECT_EQ(patches[0].at(0, 0), dvec3(1.4, 0, 2.4));   // the rim's first point
  EXPECT_EQ(patches[18].at(3, 3), dvec3(3.2, 0, 2.4));  // on the spout's opening

  TessellationReport report;
  const PolygonMesh mesh = tessellate_patches(patches, 16, &report);
  EXPECT_EQ(report.samples, 32u * 17u * 17u);
  EXPECT_EQ(report.degenerate_triangles, 8u * 16u);  // lid top and bottom centre: one row each
  EXPECT_EQ(report.vertex_splits, 1u);               // the handle touching the body
  EXPECT_EQ(mesh.positions.back(), dvec3(-2, 0, 0.9));
  EXPECT_EQ(mesh.num_vertices(), 8258u);
  EXPECT_EQ(mesh.num_faces(), 16256u);
  const HalfedgeMesh m = build_halfedge_mesh(mesh);
  EXPECT_TRUE(validate(m).ok()) << validate(m).summary();
  EXPECT_EQ(m.num_boundaries(), 6u);  // rim, lid edge, both ends of the handle and of the spout
  EXPECT_EQ(long(m.num_vertices()) - long(m.num_edges()) + long(m.num_faces()), 2);
  // Outward normals: a face at the top of the lid's knob faces up.
  size_t top = 0;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.positions[mesh.face(f)[0]].z > mesh.positions[mesh.face(top)[0]].z) top = f;
  }
  const auto t = mesh.face(top);
  EXPECT_GT(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]).z,
            0.0);
}

TEST(TeapotAsset, EveryResolutionBuilds) {
  const auto patches = read_bez(testing::source_dir() / "assets" / "teapot.bez");
  for (int n : {1, 2, 3, 5, 8, 24}) {
    const HalfedgeMesh m = build_halfedge_mesh(tessellate_patches(patches, n));
    EXPECT_TRUE(validate(m).ok()) << "resolution " << n << ": " << validate(m).summary();
  }
}

TEST(CurveDerivative, IsTheDegreeTimesTheLastPairsDifference) {
  // The hodograph of kCubic: 3 (P[i+1] - P[i]), evaluated at t.
  const std::vector<dvec2> hodograph = {{12, 24}, {12, -24}, {12, 24}};
  for (double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
    const dvec2 d = curve_derivative(kCubic, t), expected = evaluate_curve(hodograph, t);
    EXPECT_NEAR(d.x, expected.x, 1e-12) << t;
    EXPECT_NEAR(d.y, expected.y, 1e-12) << t;
  }
  EXPECT_EQ(curve_derivative(std::vector<dvec2>{{1, 2}}, 0.5), dvec2(0.0));
}

TEST(NearestOnCurve, FindsTheParameterOfAPointOnTheCurveAndOfOneBeside) {
  for (double t : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0}) {
    const CurveNearest on = nearest_on_curve(kCubic, evaluate_curve(kCubic, t));
    EXPECT_NEAR(on.t, t, 1e-6);
    EXPECT_NEAR(on.distance, 0.0, 1e-6);
  }
  // Off the curve by 0.5 along the normal at t = 0.3: the same t, at that distance.
  const dvec2 d = curve_derivative(kCubic, 0.3), normal = dvec2(-d.y, d.x) / glm::length(d);
  const dvec2 beside = evaluate_curve(kCubic, 0.3) + 0.5 * normal;
  const CurveNearest near = nearest_on_curve(kCubic, beside);
  EXPECT_NEAR(near.t, 0.3, 1e-5);
  EXPECT_NEAR(near.distance, 0.5, 1e-6);
  EXPECT_NEAR(glm::length(near.point - evaluate_curve(kCubic, 0.3)), 0.0, 1e-4);
  // Past the end: the end point.
  const CurveNearest past = nearest_on_curve(kCubic, dvec2(20, 8));
  EXPECT_EQ(past.t, 1.0);
  EXPECT_EQ(past.point, dvec2(12, 8));
}

TEST(NearestOnCurve, AnEmptyCurveHasNoNearPoint) {
  const CurveNearest none = nearest_on_curve(std::vector<dvec2>{}, dvec2(1, 1));
  EXPECT_TRUE(std::isnan(none.point.x));
  EXPECT_EQ(none.distance, kInf);
}

TEST(CurveAssets, HaveTheirPointCountsInTheUnitSquare) {
  for (const auto& [name, count] : {std::pair{"curve_cubic.bzc", 4u}, std::pair{"curve_quartic.bzc", 5u}}) {
    std::ifstream in(testing::source_dir() / "assets" / name);
    size_t n = 0;
    in >> n;
    EXPECT_EQ(n, count) << name;
    for (size_t i = 0; i < n; ++i) {
      dvec2 p(-1.0);
      in >> p.x >> p.y;
      EXPECT_TRUE(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1) << name << " point " << i;
    }
    EXPECT_FALSE(in.fail()) << name;
  }
}

TEST(CourseBez, TessellatesIntoValidHalfedgeMeshes) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  for (const char* name : {"teapot.bez", "wavy_cube.bez"}) {
    const auto patches = read_bez(dir / "bez" / name);
    ASSERT_FALSE(patches.empty()) << name;
    const HalfedgeMesh m = build_halfedge_mesh(tessellate_patches(patches));
    EXPECT_TRUE(validate(m).ok()) << name << ": " << validate(m).summary();
  }
}

}  // namespace
}  // namespace meshedit
