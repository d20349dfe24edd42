// RecordedEdit, apply_edit and replay: each kind of edit changes exactly its field, operations replay the core's
// ids, refused edits change nothing (version included) and name the element, and the texts the replay panel shows.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/edit_log.h"
#include "core/history.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

HalfedgeMesh grid() { return build_halfedge_mesh(make_grid(1, 1)); }

RecordedEdit set(ElementRef element, const char* field, ElementRef value, ElementRef before = {}) {
  RecordedEdit edit;
  edit.element = element;
  edit.field = field;
  edit.value.element = value;
  edit.before.element = before;
  return edit;
}

RecordedEdit make(EditKind what, ElementRef element, const char* field) {
  RecordedEdit edit;
  edit.what = what;
  edit.element = element;
  edit.field = field;
  return edit;
}

// The one field change `edit` made, as diff() reports it.
std::vector<FieldChange> changes(const HalfedgeMesh& mesh, const RecordedEdit& edit) {
  HalfedgeMesh after = mesh;
  apply_edit(after, edit);
  return diff(mesh, after);
}

std::string text(const std::vector<FieldChange>& list) {
  std::string out;
  for (const FieldChange& c : list) out += format_id(c.element) + "." + c.field + ":" + c.before + "->" + c.after + " ";
  return out;
}

std::string refusal(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  const uint64_t version = mesh.version();
  const HalfedgeMesh copy = mesh;
  try {
    apply_edit(mesh, edit);
  } catch (const MeshError& e) {
    EXPECT_EQ(mesh.version(), version);
    EXPECT_TRUE(mesh.same_as(copy));
    return e.what();
  }
  return "(applied)";
}

TEST(EditLog, SetWritesExactlyOneField) {
  const HalfedgeMesh m = grid();
  EXPECT_EQ(text(changes(m, set(HalfedgeId(0), "next", HalfedgeId(4)))), "h0.next:h1->h4 ");
  EXPECT_EQ(text(changes(m, set(HalfedgeId(0), "twin", ElementRef()))),
            "h0.twin:h" + std::to_string(m.twin(HalfedgeId(0)).index) + "->- ");
  EXPECT_EQ(text(changes(m, set(HalfedgeId(0), "vertex", VertexId(3)))), "h0.vertex:v0->v3 ");
  EXPECT_EQ(text(changes(m, set(HalfedgeId(0), "edge", EdgeId(4)))), "h0.edge:e0->e4 ");
  EXPECT_EQ(text(changes(m, set(HalfedgeId(0), "face", FaceId::boundary(0)))), "h0.face:f0->b0 ");
  EXPECT_EQ(text(changes(m, set(VertexId(1), "halfedge", HalfedgeId(9)))),
            "v1.halfedge:" + format_id(m.halfedge(VertexId(1))) + "->h9 ");
  EXPECT_EQ(text(changes(m, set(EdgeId(2), "halfedge", HalfedgeId(0)))),
            "e2.halfedge:" + format_id(m.halfedge(EdgeId(2))) + "->h0 ");
  EXPECT_EQ(text(changes(m, set(FaceId::boundary(0), "halfedge", HalfedgeId(7)))),
            "b0.halfedge:" + format_id(m.halfedge(FaceId::boundary(0))) + "->h7 ");
  RecordedEdit move = set(VertexId(2), "position", {});
  move.value.position = glm::dvec3(0.5, -1, 2);
  EXPECT_EQ(text(changes(m, move)), "v2.position:(0, 1, 0)->(0.5, -1, 2) ");
}

TEST(EditLog, CreateAndDelete) {
  HalfedgeMesh m = grid();
  RecordedEdit vertex = make(EditKind::Create, ElementRef(ElementKind::Vertex, 4), "alive");
  vertex.value.position = glm::dvec3(1, 2, 3);
  apply_edit(m, vertex);
  EXPECT_EQ(m.vertex_capacity(), 5u);
  EXPECT_EQ(m.position(VertexId(4)), glm::dvec3(1, 2, 3));
  apply_edit(m, make(EditKind::Create, ElementRef(ElementKind::Halfedge, 10), "alive"));
  apply_edit(m, make(EditKind::Create, ElementRef(ElementKind::Edge, 5), "alive"));
  apply_edit(m, make(EditKind::Create, ElementRef(ElementKind::Face, 2), "alive"));
  apply_edit(m, make(EditKind::Create, ElementRef(ElementKind::Boundary, 1), "alive"));
  EXPECT_TRUE(m.alive(HalfedgeId(10)) && m.alive(EdgeId(5)) && m.alive(FaceId::face(2)) &&
              m.alive(FaceId::boundary(1)));
  EXPECT_FALSE(m.next(HalfedgeId(10)).valid());
  apply_edit(m, make(EditKind::Delete, HalfedgeId(3), "alive"));
  apply_edit(m, make(EditKind::Delete, FaceId::boundary(0), "alive"));
  EXPECT_FALSE(m.alive(HalfedgeId(3)));
  EXPECT_FALSE(m.alive(FaceId::boundary(0)));
  EXPECT_TRUE(m.alive(FaceId::boundary(1)));
}

TEST(EditLog, OperationsReplayTheCoreAndRestoreTakesTheState) {
  HalfedgeMesh expected = grid();
  HalfedgeMesh m = grid();
  EdgeId interior;
  for (EdgeId e : m.edges()) {
    if (!m.is_boundary(e)) interior = e;
  }
  ASSERT_TRUE(flip(expected, interior).ok());
  ASSERT_TRUE(split(expected, EdgeId(0)).ok());
  apply_edit(m, make(EditKind::Operation, interior, "flip"));
  apply_edit(m, make(EditKind::Operation, EdgeId(0), "split"));
  EXPECT_TRUE(m.same_as(expected));

  RecordedEdit restore = make(EditKind::Operation, ElementRef(), "restore");
  restore.state = std::make_shared<const HalfedgeMesh>(grid());
  const uint64_t seen = m.version();
  apply_edit(m, restore);
  EXPECT_TRUE(m.same_as(grid()));
  EXPECT_GT(m.version(), seen);

  HalfedgeMesh big = build_halfedge_mesh(make_grid(2, 2));
  HalfedgeMesh collapsed = big;
  EdgeId accepted;
  for (EdgeId e : big.edges()) {
    if (!accepted.valid() && can_collapse(big, e).ok) accepted = e;
  }
  ASSERT_TRUE(collapse(collapsed, accepted).ok());
  apply_edit(big, make(EditKind::Operation, accepted, "collapse"));
  EXPECT_TRUE(big.same_as(collapsed));
}

TEST(EditLog, RefusedEditsChangeNothingAndNameTheElement) {
  HalfedgeMesh m = grid();
  EXPECT_EQ(refusal(m, set(HalfedgeId(10), "next", HalfedgeId(0))),
            "cannot apply 'h10.next = h0 (was -)': the mesh has no halfedge with that id (it has 10)");
  EXPECT_EQ(refusal(m, set(HalfedgeId(0), "next", VertexId(1))),
            "cannot apply 'h0.next = v1 (was -)': the value must be a halfedge");
  EXPECT_EQ(refusal(m, set(HalfedgeId(0), "face", EdgeId(1))),
            "cannot apply 'h0.face = e1 (was -)': the value must be a face");
  EXPECT_EQ(refusal(m, set(EdgeId(0), "next", HalfedgeId(1))),
            "cannot apply 'e0.next = h1 (was -)': edges have no field 'next'");
  EXPECT_EQ(refusal(m, make(EditKind::Create, ElementRef(ElementKind::Vertex, 7), "alive")),
            "cannot apply 'new v7 at (0, 0, 0)': the mesh's next vertex id is v4");
  EXPECT_EQ(refusal(m, make(EditKind::Delete, FaceId::face(2), "alive")),
            "cannot apply 'delete f2': the mesh has no face with that id (it has 2)");
  const Check refused = can_flip(m, EdgeId(0));
  ASSERT_FALSE(refused.ok);
  EXPECT_EQ(refusal(m, make(EditKind::Operation, EdgeId(0), "flip")), "cannot apply 'flip e0': " + refused.reason);
  EXPECT_EQ(refusal(m, make(EditKind::Operation, VertexId(0), "split")),
            "cannot apply 'split v0': the element must be an edge");
  EXPECT_EQ(refusal(m, make(EditKind::Operation, ElementRef(), "restore")),
            "cannot apply 'restore': the recording holds no mesh state to restore");
  EXPECT_EQ(refusal(m, make(EditKind::Operation, ElementRef(), "smooth")), "cannot apply 'smooth': unknown operation");
  // A dead element may still be written (a script can break a mesh); only unallocated ones are refused.
  m.delete_element(HalfedgeId(2));
  EXPECT_EQ(refusal(m, set(HalfedgeId(2), "next", HalfedgeId(2))), "(applied)");
}

TEST(EditLog, ReplayAppliesThePrefix) {
  const HalfedgeMesh before = grid();
  std::vector<RecordedEdit> edits = {make(EditKind::Create, ElementRef(ElementKind::Halfedge, 10), "alive"),
                                     set(HalfedgeId(10), "next", HalfedgeId(10)),
                                     set(HalfedgeId(0), "twin", HalfedgeId(10))};
  EXPECT_TRUE(replay(before, edits, 0).same_as(before));
  const HalfedgeMesh one = replay(before, edits, 1);
  EXPECT_EQ(one.halfedge_capacity(), 11u);
  EXPECT_FALSE(one.next(HalfedgeId(10)).valid());
  EXPECT_EQ(replay(before, edits, 2).next(HalfedgeId(10)), HalfedgeId(10));
  const HalfedgeMesh all = replay(before, edits, 99);  // past the end: everything
  EXPECT_EQ(all.twin(HalfedgeId(0)), HalfedgeId(10));
  EXPECT_TRUE(all.same_as(replay(before, edits, 3)));
}

TEST(EditLog, Texts) {
  RecordedEdit write = set(HalfedgeId(3), "next", HalfedgeId(7), HalfedgeId(4));
  EXPECT_EQ(describe(write), "h3.next = h7 (was h4)");
  EXPECT_EQ(format_edit_before(write), "h4");
  EXPECT_EQ(format_edit_after(write), "h7");
  EXPECT_EQ(describe(set(HalfedgeId(3), "twin", ElementRef(), HalfedgeId(4))), "h3.twin = - (was h4)");
  RecordedEdit move = set(VertexId(1), "position", {});
  move.before.position = glm::dvec3(0.1, 0, 0);
  move.value.position = glm::dvec3(0.5, 0, -0.0);
  EXPECT_EQ(describe(move), "v1.position = (0.5, 0, -0) (was (0.1, 0, 0))");
  RecordedEdit vertex = make(EditKind::Create, VertexId(9), "alive");
  vertex.value.position = glm::dvec3(0.5, 0, 0);
  EXPECT_EQ(describe(vertex), "new v9 at (0.5, 0, 0)");
  EXPECT_EQ(format_edit_before(vertex) + " " + format_edit_after(vertex), "- alive");
  EXPECT_EQ(describe(make(EditKind::Create, HalfedgeId(12), "alive")), "new h12");
  const RecordedEdit gone = make(EditKind::Delete, HalfedgeId(7), "alive");
  EXPECT_EQ(describe(gone), "delete h7");
  EXPECT_EQ(format_edit_before(gone) + " " + format_edit_after(gone), "alive dead");
  EXPECT_EQ(describe(make(EditKind::Operation, EdgeId(3), "flip")), "flip e3");
  RecordedEdit split_edit = make(EditKind::Operation, EdgeId(3), "split");
  split_edit.value.element = VertexId(9);
  EXPECT_EQ(describe(split_edit), "split e3 -> v9");
  EXPECT_EQ(format_edit_after(split_edit), "v9");
  EXPECT_EQ(describe(make(EditKind::Operation, ElementRef(), "loop_subdivide")), "loop_subdivide");
  EXPECT_STREQ(edit_kind_name(EditKind::Set), "set");
  EXPECT_STREQ(edit_kind_name(EditKind::Create), "new");
  EXPECT_STREQ(edit_kind_name(EditKind::Delete), "delete");
  EXPECT_STREQ(edit_kind_name(EditKind::Operation), "operation");
}

}  // namespace
}  // namespace meshedit
