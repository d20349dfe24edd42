// Building half-edge meshes from polygons: exact ids and pointers, boundaries, and every refusal.
#include <gtest/gtest.h>

#include <string>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_stats.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

HalfedgeId H(uint32_t i) { return HalfedgeId(i); }
VertexId V(uint32_t i) { return VertexId(i); }
EdgeId E(uint32_t i) { return EdgeId(i); }

// The message of the MeshError that building `polygons` throws ("" if it builds).
std::string refusal(const PolygonMesh& polygons) {
  try {
    build_halfedge_mesh(polygons);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

PolygonMesh points(uint32_t n) {
  PolygonMesh m;
  for (uint32_t i = 0; i < n; ++i) m.add_vertex({double(i), double(i * i % 7), double(i % 3)});
  return m;
}

TEST(MeshBuild, SquareOfTwoTrianglesHasDocumentedIds) {
  // v2---v3      f0 = (0 1 3): h0 0->1, h1 1->3, h2 3->0
  //  | f1/ |     f1 = (0 3 2): h3 0->3, h4 3->2, h5 2->0
  //  | /f0 |     boundary b0 walks 1->0->2->3->1: h6 h7 h8 h9
  // v0---v1
  const HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  ASSERT_EQ(m.num_halfedges(), 10u);
  ASSERT_EQ(m.num_edges(), 5u);
  ASSERT_EQ(m.num_boundaries(), 1u);
  const FaceId f0 = FaceId::face(0), f1 = FaceId::face(1), b0 = FaceId::boundary(0);

  struct Row {
    uint32_t next, twin, vertex, edge;
    FaceId face;
  };
  const Row expected[10] = {
      {1, 6, 0, 0, f0}, {2, 9, 1, 1, f0}, {0, 3, 3, 2, f0}, {4, 2, 0, 2, f1}, {5, 8, 3, 3, f1},
      {3, 7, 2, 4, f1}, {7, 0, 1, 0, b0}, {8, 5, 0, 4, b0}, {9, 4, 2, 3, b0}, {6, 1, 3, 1, b0},
  };
  for (uint32_t h = 0; h < 10; ++h) {
    SCOPED_TRACE("h" + std::to_string(h));
    EXPECT_EQ(m.next(H(h)), H(expected[h].next));
    EXPECT_EQ(m.twin(H(h)), H(expected[h].twin));
    EXPECT_EQ(m.vertex(H(h)), V(expected[h].vertex));
    EXPECT_EQ(m.edge(H(h)), E(expected[h].edge));
    EXPECT_EQ(m.face(H(h)), expected[h].face);
  }
  // Boundary vertices keep their outgoing boundary halfedge.
  EXPECT_EQ(m.halfedge(V(0)), H(7));
  EXPECT_EQ(m.halfedge(V(1)), H(6));
  EXPECT_EQ(m.halfedge(V(2)), H(8));
  EXPECT_EQ(m.halfedge(V(3)), H(9));
  const uint32_t edge_halfedges[5] = {0, 1, 2, 4, 5};
  for (uint32_t e = 0; e < 5; ++e) EXPECT_EQ(m.halfedge(E(e)), H(edge_halfedges[e]));
  EXPECT_EQ(m.halfedge(f0), H(0));
  EXPECT_EQ(m.halfedge(f1), H(3));
  EXPECT_EQ(m.halfedge(b0), H(6));
  EXPECT_EQ(m.position(V(3)), glm::dvec3(1, 1, 0));
  EXPECT_TRUE(m.is_boundary(E(0)));
  EXPECT_FALSE(m.is_boundary(E(2)));
  EXPECT_EQ(m.degree(V(0)), 3u);  // two faces and the boundary loop
}

TEST(MeshBuild, InteriorVertexTakesItsLowestOutgoingHalfedge) {
  const HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  // Tetrahedron faces (0 1 2) (0 3 1) (0 2 3) (1 3 2): v1 leaves first at h1, v3 at h4.
  EXPECT_EQ(m.halfedge(V(0)), H(0));
  EXPECT_EQ(m.halfedge(V(1)), H(1));
  EXPECT_EQ(m.halfedge(V(2)), H(2));
  EXPECT_EQ(m.halfedge(V(3)), H(4));
  EXPECT_EQ(m.twin(H(0)), H(5));  // 0->1 pairs with 1->0 (second corner of face 1)
  EXPECT_EQ(m.degree(V(0)), 3u);
  EXPECT_EQ(m.degree(FaceId::face(3)), 3u);
}

TEST(MeshBuild, FixturesHaveExpectedTopology) {
  struct Case {
    const char* name;
    PolygonMesh mesh;
    size_t v, e, f, b;
    long chi;
    long genus;
  };
  const Case cases[] = {
      {"tetrahedron", make_tetrahedron(), 4, 6, 4, 0, 2, 0}, {"cube", make_cube(), 8, 18, 12, 0, 2, 0},
      {"cube_quads", make_cube_quads(), 8, 12, 6, 0, 2, 0},  {"icosahedron", make_icosahedron(), 12, 30, 20, 0, 2, 0},
      {"grid", make_grid(3, 2), 12, 23, 12, 1, 1, 0},        {"fan", make_fan(50), 51, 100, 50, 1, 1, 0},
      {"torus", make_torus(8, 4), 32, 96, 64, 0, 0, 1},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const HalfedgeMesh m = build_halfedge_mesh(c.mesh);
    const MeshStats s = compute_stats(m);
    EXPECT_EQ(s.vertices, c.v);
    EXPECT_EQ(s.edges, c.e);
    EXPECT_EQ(s.faces, c.f);
    EXPECT_EQ(s.halfedges, 2 * c.e);
    EXPECT_EQ(s.boundary_loops, c.b);
    EXPECT_EQ(s.euler_characteristic, c.chi);
    EXPECT_EQ(s.components, 1u);
    ASSERT_TRUE(s.genus.has_value());
    EXPECT_EQ(*s.genus, c.genus);
  }
}

TEST(MeshBuild, TwoComponentsCountSeparately) {
  PolygonMesh m = make_tetrahedron();
  m.append(make_icosahedron());
  const MeshStats s = compute_stats(build_halfedge_mesh(m));
  EXPECT_EQ(s.components, 2u);
  EXPECT_EQ(s.euler_characteristic, 4);
  EXPECT_EQ(s.genus, 0);
}

TEST(MeshBuild, UnusedVerticesKeepTheirIdsAsDeadSlots) {
  PolygonMesh m = points(5);
  m.add_face({0, 1, 2});
  m.add_face({2, 1, 3});
  BuildReport report;
  const HalfedgeMesh mesh = build_halfedge_mesh(m, &report);
  EXPECT_EQ(report.unused_vertices, 1u);
  EXPECT_EQ(mesh.num_vertices(), 4u);
  EXPECT_EQ(mesh.vertex_capacity(), 5u);
  EXPECT_FALSE(mesh.alive(V(4)));
  EXPECT_TRUE(mesh.alive(V(3)));
}

TEST(MeshBuild, RefusesFaceWithTooFewCorners) {
  PolygonMesh m = points(3);
  m.add_face({0, 1});
  EXPECT_EQ(refusal(m), "face 0 has 2 corners; a face needs at least 3");
}

TEST(MeshBuild, RefusesOutOfRangeIndex) {
  PolygonMesh m = points(3);
  m.add_face({0, 1, 2});
  m.add_face({2, 1, 7});
  EXPECT_EQ(refusal(m), "face 1 refers to vertex 7, but there are only 3 vertices");
}

TEST(MeshBuild, RefusesDegenerateFace) {
  PolygonMesh m = points(4);
  m.add_face({0, 1, 2, 1});
  EXPECT_EQ(refusal(m), "face 0 is degenerate: it uses vertex 1 twice");
}

TEST(MeshBuild, RefusesEdgeWithThreeFaces) {
  PolygonMesh m = points(5);
  m.add_face({0, 1, 2});
  m.add_face({1, 0, 3});
  m.add_face({0, 1, 4});
  EXPECT_EQ(refusal(m),
            "the edge between vertices 0 and 1 is shared by 3 faces (0, 1 and 2); a manifold edge has at most two");
}

TEST(MeshBuild, RefusesInconsistentOrientation) {
  PolygonMesh m = points(4);
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 3});
  EXPECT_EQ(refusal(m),
            "faces 0 and 1 both go from vertex 0 to vertex 1: their orientations are inconsistent (flip one of them)");
}

TEST(MeshBuild, RefusesRepeatedFace) {
  PolygonMesh same = points(3);
  same.add_face({0, 1, 2});
  same.add_face({1, 2, 0});
  EXPECT_EQ(refusal(same), "face 1 repeats face 0 (same vertices)");

  PolygonMesh pillow = points(3);
  pillow.add_face({0, 1, 2});
  pillow.add_face({2, 1, 0});
  EXPECT_EQ(refusal(pillow), "face 1 repeats face 0 (same vertices, opposite orientation)");
}

TEST(MeshBuild, RefusesBowTieOnTwoHoles) {
  PolygonMesh m = points(5);
  m.add_face({0, 1, 2});
  m.add_face({0, 3, 4});
  EXPECT_EQ(refusal(m), "vertex 0 is a bow-tie: faces 0 and 1 touch only at this vertex, on two different holes");
}

TEST(MeshBuild, RefusesClosedSurfacesTouchingAtOneVertex) {
  // Two tetrahedra sharing vertex 0: every edge is fine, but v0 has two separate fans.
  PolygonMesh m = make_tetrahedron();
  PolygonMesh second = make_tetrahedron();
  for (auto& p : second.positions) p += glm::dvec3(2, 0, 0);
  m.append(second);
  for (size_t i = 12; i < m.indices.size(); ++i) {
    if (m.indices[i] == 4) m.indices[i] = 0;  // glue the second tetrahedron's vertex 0 onto the first's
  }
  const std::string why = refusal(m);
  EXPECT_NE(why.find("vertex 0 is a bow-tie: its faces form separate fans (faces 0, 1 and 2 on one, faces 4, 5 and 6"),
            std::string::npos)
      << why;
}

TEST(MeshBuild, RefusesBadOffsets) {
  PolygonMesh m = points(3);
  m.indices = {0, 1, 2};
  m.face_offsets = {0, 2};
  EXPECT_EQ(refusal(m), "polygon offsets do not match the index list");
}

TEST(MeshBuild, RoundTripsThroughPolygons) {
  const PolygonMesh original = make_icosahedron();
  const PolygonMesh back = to_polygon_mesh(build_halfedge_mesh(original));
  EXPECT_EQ(back.positions, original.positions);
  EXPECT_EQ(back.indices, original.indices);
  EXPECT_EQ(back.face_offsets, original.face_offsets);
}

TEST(MeshBuild, ExportNamesTheBrokenFace) {
  HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  m.set_next(H(2), H(3));  // f0's cycle now runs into f1 and never returns to h0
  try {
    to_polygon_mesh(m);
    FAIL() << "expected a MeshError";
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(), "cannot export f0: its next-cycle does not close");
    EXPECT_EQ(e.element(), ElementRef(FaceId::face(0)));
  }
}

}  // namespace
}  // namespace meshedit
