// The triangle rows Loop subdivision leaves on its result (triangle_rows.h): every face once with the corners of its
// own cycle, each face's four children in four consecutive rows in the order of the rows before (so a second call
// continues the first's order), the same for one call or several and for any thread count; kept while only
// positions change and shared by copies; dropped by any other change. The seam between runs of rows is the vertices
// two runs share, made once and kept. Normals on the rows agree with vertex_normal.
#include <algorithm>
#include <array>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/normals.h"
#include "core/parallel_for.h"
#include "core/primitives.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

// Whether `mesh` has rows listing each live face once, with the corners of its cycle from its halfedge.
::testing::AssertionResult rows_list_every_face(const HalfedgeMesh& mesh) {
  const TriangleRows* rows = mesh.triangle_rows();
  if (!rows) return ::testing::AssertionFailure() << "no rows";
  if (rows->size() != mesh.num_faces()) {
    return ::testing::AssertionFailure() << rows->size() << " rows for " << mesh.num_faces() << " faces";
  }
  std::vector<int> seen(mesh.face_capacity(), 0);
  for (size_t r = 0; r < rows->size(); ++r) {
    const TriangleRow& row = (*rows)[r];
    if (!mesh.alive(row.face)) return ::testing::AssertionFailure() << "row " << r << ": dead face";
    if (++seen[row.face.slot()] > 1) return ::testing::AssertionFailure() << "f" << row.face.slot() << " twice";
    HalfedgeId h = mesh.halfedge(row.face);
    for (int k = 0; k < 3; ++k, h = mesh.next(h)) {
      if (mesh.vertex(h) != row.corner[k]) {
        return ::testing::AssertionFailure() << "row " << r << " (f" << row.face.slot() << "): corner " << k << " is v"
                                             << row.corner[k].index << ", the face's is v" << mesh.vertex(h).index;
      }
    }
    if (mesh.next(h) != mesh.halfedge(row.face) && h != mesh.halfedge(row.face)) {
      return ::testing::AssertionFailure() << "f" << row.face.slot() << " is not a triangle";
    }
  }
  return ::testing::AssertionSuccess();
}

std::vector<std::array<uint32_t, 4>> row_values(const HalfedgeMesh& mesh) {
  std::vector<std::array<uint32_t, 4>> out;
  for (const TriangleRow& row : *mesh.triangle_rows()) {
    out.push_back({row.corner[0].index, row.corner[1].index, row.corner[2].index, row.face.slot()});
  }
  return out;
}

TEST(TriangleRows, LoopListsEveryFaceOnceWithItsCorners) {
  const std::pair<const char*, PolygonMesh> fixtures[] = {{"icosahedron", make_icosahedron()},
                                                          {"grid (boundary)", make_grid(5, 4)},
                                                          {"torus", make_torus(9, 7)},
                                                          {"tetrahedron", make_tetrahedron()}};
  for (const auto& [name, polygons] : fixtures) {
    SCOPED_TRACE(name);
    HalfedgeMesh mesh = build_halfedge_mesh(polygons);
    EXPECT_EQ(mesh.triangle_rows(), nullptr);  // the builder leaves none
    for (int levels = 1; levels <= 2; ++levels) {
      HalfedgeMesh m = mesh;
      ASSERT_TRUE(loop_subdivide(m, LoopWeights::Loop, levels, 1));
      EXPECT_TRUE(rows_list_every_face(m)) << levels << " levels";
    }
  }
}

// Rows 4k..4k+3 are the faces of the k-th face before: their corners from before the level are that face's three
// corners, one each, and they have three new vertices between them. The k-th face is the k-th row before, or the
// k-th live face when there were no rows (here: after edits left dead faces).
TEST(TriangleRows, EachFacesFourChildrenTakeFourRowsInTheOrderBefore) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(12, 8));
  testing::random_local_edits(mesh, 7, 30);
  std::vector<std::array<uint32_t, 3>> parents;  // the faces before, in order: live faces, then the first rows
  for (FaceId f : mesh.faces()) {
    HalfedgeId h = mesh.halfedge(f);
    parents.push_back(
        {mesh.vertex(h).index, mesh.vertex(mesh.next(h)).index, mesh.vertex(mesh.next(mesh.next(h))).index});
  }
  for (int call = 0; call < 2; ++call) {
    SCOPED_TRACE("call " + std::to_string(call));
    const uint32_t old_vertices = mesh.vertex_capacity();
    ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Loop, 1, 1));
    const TriangleRows& rows = *mesh.triangle_rows();
    ASSERT_EQ(rows.size(), 4 * parents.size());
    for (size_t k = 0; k < parents.size(); ++k) {
      std::multiset<uint32_t> old_corners;
      std::set<uint32_t> new_corners;
      for (size_t r = 4 * k; r < 4 * k + 4; ++r) {
        for (VertexId c : rows[r].corner) {
          if (c.index < old_vertices) old_corners.insert(c.index);
          else new_corners.insert(c.index);
        }
      }
      EXPECT_EQ(old_corners, std::multiset<uint32_t>(parents[k].begin(), parents[k].end())) << "group " << k;
      EXPECT_EQ(new_corners.size(), 3u) << "group " << k;
    }
    parents.clear();
    for (const TriangleRow& row : rows)
      parents.push_back({row.corner[0].index, row.corner[1].index, row.corner[2].index});
  }
}

TEST(TriangleRows, OneCallOrSeveralAndAnyThreadCountGiveTheSameRows) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(3000));
  HalfedgeMesh once = mesh, twice = mesh, threaded = mesh;
  ASSERT_TRUE(loop_subdivide(once, LoopWeights::Loop, 2, 1));
  ASSERT_TRUE(loop_subdivide(twice, LoopWeights::Loop, 1, 1));
  ASSERT_TRUE(loop_subdivide(twice, LoopWeights::Loop, 1, 1));
  ASSERT_TRUE(loop_subdivide(threaded, LoopWeights::Loop, 2, 2));
  EXPECT_TRUE(once.same_as(twice));
  EXPECT_EQ(row_values(once), row_values(twice));
  EXPECT_EQ(row_values(once), row_values(threaded));
}

TEST(TriangleRows, KeptWhilePositionsMoveAndSharedByCopiesDroppedByAnyOtherChange) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_icosahedron());
  ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Loop, 1, 1));
  const TriangleRows* rows = mesh.triangle_rows();
  ASSERT_NE(rows, nullptr);
  mesh.set_position(VertexId(4), mesh.position(VertexId(4)) * 1.5);
  EXPECT_EQ(mesh.triangle_rows(), rows);
  EXPECT_FALSE(mesh.proven_valid_triangles());  // the proof covers positions too; the rows only connectivity
  const HalfedgeMesh copy = mesh;
  EXPECT_EQ(copy.triangle_rows(), rows);
  EXPECT_GT(mesh.memory_bytes(), build_halfedge_mesh(make_icosahedron()).memory_bytes());

  HalfedgeMesh flipped = mesh;
  ASSERT_TRUE(flip(flipped, EdgeId(0)));
  EXPECT_EQ(flipped.triangle_rows(), nullptr);
  HalfedgeMesh written = mesh;
  written.set_next(HalfedgeId(0), written.next(HalfedgeId(0)));  // even a write of the same value
  EXPECT_EQ(written.triangle_rows(), nullptr);

  // Undo puts back the mesh before Loop (no rows); redo brings the subdivided one back, as it was kept.
  HalfedgeMesh undone = build_halfedge_mesh(make_icosahedron());
  History history;
  history.record("Loop", undone);
  ASSERT_TRUE(loop_subdivide(undone, LoopWeights::Loop, 1, 1));
  ASSERT_TRUE(history.undo(undone));
  EXPECT_EQ(undone.triangle_rows(), nullptr);
  ASSERT_TRUE(history.redo(undone));
  EXPECT_TRUE(rows_list_every_face(undone));
}

// The seam for the runs a pass on `threads` threads cuts the rows into: each vertex's bit set exactly when rows of two
// runs or more have it as a corner (counted here run by run), none for one run. Made once per run count and kept
// with the rows, by the mesh and its copies; several threads asking at once get the same bits.
TEST(TriangleRows, TheSeamIsEveryVertexTwoRunsShareMadeOnceAndKept) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(20000));
  ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Loop, 1, 1));
  const TriangleRows& rows = *mesh.triangle_rows();
  const size_t vertices = mesh.vertex_capacity();
  for (int threads : {2, 3, 1, 2}) {
    const size_t runs = chunk_count(threads, rows.size());
    std::vector<std::set<size_t>> runs_of(vertices);
    for (size_t run = 0; run < runs; ++run) {
      for (size_t r = chunk_begin(run, runs, rows.size()); r < chunk_begin(run + 1, runs, rows.size()); ++r) {
        for (VertexId c : rows[r].corner) runs_of[c.index].insert(run);
      }
    }
    const std::shared_ptr<const VertexBits> seam = rows.seam_between_runs(threads, vertices);
    ASSERT_EQ(seam->size(), (vertices + 63) / 64);
    size_t on_seam = 0;
    for (size_t v = 0; v < vertices; ++v) {
      const bool bit = vertex_bit(seam->data(), VertexId(uint32_t(v)));
      EXPECT_EQ(bit, runs_of[v].size() > 1) << "v" << v << ", " << threads << " threads";
      on_seam += bit ? 1 : 0;
    }
    if (runs > 1) EXPECT_GT(on_seam, 0u) << threads << " threads";
    else EXPECT_EQ(on_seam, 0u);
    EXPECT_EQ(rows.seam_between_runs(threads, vertices), seam) << "kept";
    const HalfedgeMesh copy = mesh;
    EXPECT_EQ(copy.triangle_rows()->seam_between_runs(threads, vertices), seam) << "kept for copies";
  }

  HalfedgeMesh fresh = build_halfedge_mesh(make_torus_with_faces(20000));
  ASSERT_TRUE(loop_subdivide(fresh, LoopWeights::Loop, 1, 1));
  std::vector<std::shared_ptr<const VertexBits>> asked(4);
  std::vector<std::thread> askers;
  for (size_t i = 0; i < asked.size(); ++i) {
    askers.emplace_back([&, i] { asked[i] = fresh.triangle_rows()->seam_between_runs(2, vertices); });
  }
  for (std::thread& t : askers) t.join();
  const std::shared_ptr<const VertexBits> first = rows.seam_between_runs(2, vertices);
  for (const std::shared_ptr<const VertexBits>& bits : asked) EXPECT_TRUE(*bits == *first);
}

// After Loop and a vertex moved, the rows still serve vertex_normals: each vertex's normal as vertex_normal gives it,
// to rounding, on one thread or two.
TEST(TriangleRows, NormalsOnTheRowsAgreeWithThePerVertexNormal) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(30, 20));
  ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Loop, 2, 1));
  mesh.set_position(VertexId(40), mesh.position(VertexId(40)) + glm::dvec3(0.0, 0.0, 0.3));
  ASSERT_NE(mesh.triangle_rows(), nullptr);
  for (int threads = 1; threads <= 2; ++threads) {
    const std::vector<glm::dvec3> all = vertex_normals(mesh, threads);
    for (VertexId v : mesh.vertices()) {
      const glm::dvec3 one = vertex_normal(mesh, v);
      EXPECT_NEAR(all[v.index].x, one.x, 1e-13) << "v" << v.index;
      EXPECT_NEAR(all[v.index].y, one.y, 1e-13) << "v" << v.index;
      EXPECT_NEAR(all[v.index].z, one.z, 1e-13) << "v" << v.index;
    }
  }
  EXPECT_GT(vertex_normal(mesh, VertexId(40)).z, 0.0);
}

}  // namespace
}  // namespace meshedit
