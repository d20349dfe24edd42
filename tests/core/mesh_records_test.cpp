// core/mesh_records.h: a mesh with every record (dead slots, broken pointers, boundary loops) as text and back, and
// the refusals of a damaged text, each naming its line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/mesh_records.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

// A grid a split and a flip changed, with a dead face still pointed to and a broken next: what a student leaves.
HalfedgeMesh edited_grid() {
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(3, 3));
  std::vector<EdgeId> interior;
  for (const EdgeId e : mesh.edges()) {
    if (!mesh.is_boundary(e)) interior.push_back(e);
  }
  EXPECT_TRUE(split(mesh, interior[0]).ok());
  EXPECT_TRUE(flip(mesh, interior[3]).ok());
  mesh.delete_element(FaceId::face(2));
  mesh.set_next(HalfedgeId(0), HalfedgeId(7));
  mesh.set_position(VertexId(1), glm::dvec3(0.1, -1e-300, 1.0 / 3.0));
  return mesh;
}

TEST(MeshRecords, EveryRecordReadsBack) {
  const HalfedgeMesh mesh = edited_grid();
  const HalfedgeMesh back = parse_mesh_records(format_mesh_records(mesh), "grid");
  ASSERT_EQ(back.vertex_capacity(), mesh.vertex_capacity());
  ASSERT_EQ(back.halfedge_capacity(), mesh.halfedge_capacity());
  ASSERT_EQ(back.edge_capacity(), mesh.edge_capacity());
  ASSERT_EQ(back.face_capacity(), mesh.face_capacity());
  ASSERT_EQ(back.boundary_capacity(), mesh.boundary_capacity());
  for (uint32_t i = 0; i < mesh.vertex_capacity(); ++i) {
    EXPECT_EQ(back.position(VertexId(i)), mesh.position(VertexId(i)));  // exactly: the shortest text reads back
    EXPECT_EQ(back.halfedge(VertexId(i)), mesh.halfedge(VertexId(i)));
  }
  for (uint32_t i = 0; i < mesh.halfedge_capacity(); ++i) {
    EXPECT_EQ(back.alive(HalfedgeId(i)), mesh.alive(HalfedgeId(i)));
    EXPECT_EQ(back.record(HalfedgeId(i)), mesh.record(HalfedgeId(i))) << "h" << i;
  }
  EXPECT_EQ(back.next(HalfedgeId(0)), HalfedgeId(7));  // the broken pointer, kept
  EXPECT_FALSE(back.alive(FaceId::face(2)));
  for (uint32_t i = 0; i < mesh.boundary_capacity(); ++i) {
    EXPECT_EQ(back.halfedge(FaceId::boundary(i)), mesh.halfedge(FaceId::boundary(i)));
  }
  EXPECT_EQ(format_mesh_records(back), format_mesh_records(mesh));
}

TEST(MeshRecords, ADamagedTextIsRefusedWithItsLine) {
  const std::string records = format_mesh_records(edited_grid());
  const auto refusal = [](const std::string& text) {
    try {
      parse_mesh_records(text, "case");
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("v 0 + 0 0 0 h0\n"), "case:1: not a MeshEdit mesh records text (no \"meshedit mesh records 1\")");
  std::string far = records;
  far.replace(far.find(" h0 "), 4, " h999 ");
  EXPECT_NE(refusal(far).find("h999 is not a slot of this text"), std::string::npos) << refusal(far);
  std::string skipped = records;
  skipped.erase(skipped.find("v 1 "), skipped.find('\n', skipped.find("v 1 ")) - skipped.find("v 1 ") + 1);
  EXPECT_NE(refusal(skipped).find("case:3: v 2 is out of order (expected 1)"), std::string::npos) << refusal(skipped);
  EXPECT_NE(refusal(std::string(records).replace(records.find("v 0 +"), 5, "v 0 ?")).find("is not + (live)"),
            std::string::npos);
  // Cut before its halfedges: the vertices point to slots the text does not have.
  EXPECT_EQ(refusal(records.substr(0, records.find("\nh 0"))), "case:2: h55 is not a slot of this text");
}

}  // namespace
}  // namespace meshedit
