// Edit > Triangulate on the document: one undoable step that turns a quad mesh into triangles.
#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/document_actions.h"
#include "document/document_test_support.h"

namespace meshedit {
namespace {

TEST(TriangulateAction, QuadCubeIsTriangulatedAsOneUndoableStep) {
  const HalfedgeMesh quads = build_halfedge_mesh(make_cube_quads());
  MeshDocument doc = make_document(quads);
  Selection sel{FaceId(3), {}};
  EXPECT_FALSE(loop_subdivide_all(doc, sel).ok);
  EXPECT_NE(doc.message.text.find("Edit > Triangulate"), std::string::npos) << doc.message.text;
  ASSERT_TRUE(triangulate_all(doc, sel).ok) << doc.message.text;
  EXPECT_EQ(doc.mesh.num_faces(), 12u);
  EXPECT_EQ(doc.mesh.num_vertices(), 8u);
  EXPECT_EQ(doc.last.label, "Triangulate every face");
  EXPECT_NE(doc.message.text.find("6 faces split into 12 triangles"), std::string::npos) << doc.message.text;
  EXPECT_EQ(sel.selected, ElementRef());  // ids were renumbered
  ASSERT_TRUE(loop_subdivide_all(doc, sel).ok);
  EXPECT_EQ(doc.mesh.num_faces(), 48u);
  ASSERT_TRUE(undo_edit(doc, sel));
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_TRUE(doc.mesh.same_as(quads));
  ASSERT_TRUE(redo_edit(doc, sel));
  EXPECT_EQ(doc.mesh.num_faces(), 12u);
}

TEST(TriangulateAction, ATriangleMeshIsLeftAsItIs) {
  const HalfedgeMesh tet = build_halfedge_mesh(make_tetrahedron());
  MeshDocument doc = make_document(tet);
  Selection sel;
  ASSERT_TRUE(triangulate_all(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(tet));
  EXPECT_NE(doc.message.text.find("every face was already a triangle"), std::string::npos) << doc.message.text;
}

}  // namespace
}  // namespace meshedit
