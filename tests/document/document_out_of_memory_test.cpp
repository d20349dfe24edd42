// MeshDocument when memory runs out saving the state before an operation (FailingSnapshots makes the journal's
// snapshot throw std::bad_alloc): Loop subdivision (MeshStorage::grow), direct array writes, assignments, moves,
// swaps and scripts past the log cap keep exactly what they make of a mesh without a journal, and so does an
// operation that then refuses or throws; undo and redo history is cleared, `last` is marked not recorded, the message
// names the cause, and the next edit, undo and redo work normally.
#include <stdexcept>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "document/mesh_document.h"
#include "support/failing_snapshots.h"
#include "support/next_edit_check.h"

namespace meshedit {
namespace {

const std::string kCause = "memory ran out saving the mesh before it";

// A torus document with history to lose: two flips, the second undone, so there is both undo and redo.
MeshDocument document_with_history() {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  EXPECT_TRUE(apply_operation(doc, "flip", [](HalfedgeMesh& m) { return flip(m, EdgeId(4)); }).ok());
  EXPECT_TRUE(apply_operation(doc, "flip", [](HalfedgeMesh& m) { return flip(m, EdgeId(9)); }).ok());
  EXPECT_TRUE(undo(doc));
  EXPECT_TRUE(doc.history.can_undo());
  EXPECT_TRUE(doc.history.can_redo());
  return doc;
}

// `op` as the document runs it, on a mesh without a journal: an exception counts as a refusal.
template <class Op>
bool run_plain(HalfedgeMesh& mesh, Op& op) {
  try {
    return op(mesh).ok;
  } catch (const std::exception&) {
    return false;
  }
}

// Runs `op` as "big" with failing snapshots and checks the document kept exactly what `op` makes of a plain copy of
// the mesh, dropped its history, marked `last` not recorded and said why; then that the next edit records, undoes
// and redoes as usual.
template <class Op>
void expect_kept_but_not_recorded(MeshDocument& doc, Op op) {
  HalfedgeMesh expected = doc.mesh;  // a copy: no journal
  const bool accepted = run_plain(expected, op);
  const uint64_t version_before = doc.mesh.version(), serial = doc.last.serial;
  Check check;
  {
    const testing::FailingSnapshots failing;
    check = apply_operation(doc, "big", op);  // no std::terminate
  }
  EXPECT_EQ(check.ok, accepted);
  EXPECT_TRUE(doc.mesh.same_as(expected));
  EXPECT_EQ(doc.mesh.num_faces(), expected.num_faces());
  EXPECT_GT(doc.mesh.version(), version_before);
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_FALSE(doc.history.can_redo());
  EXPECT_FALSE(doc.last.recorded);
  EXPECT_EQ(doc.last.label, "big");
  EXPECT_FALSE(doc.last.before.has_value());
  EXPECT_FALSE(doc.last.patch.has_value());
  EXPECT_FALSE(doc.last.version_before.has_value());
  EXPECT_TRUE(doc.last.changes.empty());
  EXPECT_EQ(doc.last.version_after, doc.mesh.version());
  EXPECT_EQ(doc.last.serial, serial + 1);
  if (accepted) {
    EXPECT_EQ(doc.message.severity, Severity::Warning);
    EXPECT_EQ(doc.message.text, "big: done, but " + kCause + ", so it cannot be undone: undo history cleared");
  } else {
    EXPECT_EQ(doc.message.severity, Severity::Error);
    EXPECT_EQ(doc.message.text, "big: " + check.reason + "; " + kCause +
                                    ", so it could not be undone: the mesh is as the operation left it, undo history "
                                    "cleared");
  }
  EXPECT_FALSE(undo(doc));
  EXPECT_EQ(doc.message.text, "nothing to undo");
  EXPECT_TRUE(doc.mesh.same_as(expected));

  // The next edit is recorded and undone as usual, and it is the only entry: redo brings it back.
  testing::expect_next_edit_recorded(doc, [&] { return undo(doc); });
  EXPECT_FALSE(doc.history.can_undo());
  ASSERT_TRUE(redo(doc));
  EXPECT_EQ(doc.mesh.position(VertexId(0)), glm::dvec3(0.125, 2, 3));
}

TEST(DocumentOutOfMemory, LoopSubdivisionKeepsItsResult) {
  MeshDocument doc = document_with_history();
  const size_t faces = doc.mesh.num_faces();
  expect_kept_but_not_recorded(doc, [](HalfedgeMesh& m) { return loop_subdivide(m); });
  EXPECT_EQ(doc.mesh.num_faces(), 4 * faces);
}

TEST(DocumentOutOfMemory, DirectArrayWritesKeepTheirResult) {
  MeshDocument doc = document_with_history();
  expect_kept_but_not_recorded(doc, [](HalfedgeMesh& m) {
    m.set_position(VertexId(3), {1, 1, 1});
    MeshStorage::view(m).position[4] = glm::dvec3(9);
    MeshStorage::touch(m);
    return Check::yes();
  });
}

TEST(DocumentOutOfMemory, AssignmentsMovesAndSwapsKeepTheirResult) {
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  MeshDocument doc = document_with_history();
  expect_kept_but_not_recorded(doc, [&](HalfedgeMesh& m) {
    m = cube;  // an older version() than the document's: the document moves it above
    return Check::yes();
  });
  doc = document_with_history();
  expect_kept_but_not_recorded(doc, [](HalfedgeMesh& m) {
    HalfedgeMesh taken = std::move(m);  // the mesh's noexcept move constructor falls back
    taken.set_position(VertexId(2), {1, 2, 3});
    m = std::move(taken);
    return Check::yes();
  });
  doc = document_with_history();
  expect_kept_but_not_recorded(doc, [&](HalfedgeMesh& m) {
    HalfedgeMesh other = cube;
    std::swap(m, other);
    m.set_position(VertexId(1), {4, 5, 6});
    return Check::yes();
  });
}

TEST(DocumentOutOfMemory, AScriptPastTheLogCapKeepsItsResult) {
  MeshDocument doc = document_with_history();
  expect_kept_but_not_recorded(doc, [](HalfedgeMesh& m) {
    for (uint32_t i = 0; i < 10000; ++i) m.set_position(VertexId(i % m.vertex_capacity()), glm::dvec3(i, 0.5, 1));
    return Check::yes();
  });
}

// How the next test's operation fails after it wrote, fell back (direct array access) and wrote again: the document
// cannot put the mesh back, so it keeps it as the operation left it and says so.
enum class Failure { Refuse, ThrowMeshError, ThrowStd };

TEST(DocumentOutOfMemory, ARefusedOrThrowingOperationIsKeptAsItLeftTheMesh) {
  for (const Failure failure : {Failure::Refuse, Failure::ThrowMeshError, Failure::ThrowStd}) {
    SCOPED_TRACE(static_cast<int>(failure));
    MeshDocument doc = document_with_history();
    expect_kept_but_not_recorded(doc, [failure](HalfedgeMesh& m) {
      m.set_next(HalfedgeId(0), HalfedgeId(9));
      MeshStorage::view(m).position[1] = glm::dvec3(7);
      MeshStorage::touch(m);
      m.delete_element(EdgeId(2));
      switch (failure) {
        case Failure::Refuse: return Check::no("not today");
        case Failure::ThrowMeshError: throw MeshError("broken", ElementRef(EdgeId(2)));
        case Failure::ThrowStd: throw std::runtime_error("boom");
      }
      return Check::yes();
    });
  }
}

TEST(DocumentOutOfMemory, TheCulpritOfAThrowingOperationIsOffered) {
  MeshDocument doc = document_with_history();
  const testing::FailingSnapshots failing;
  const Check check = apply_operation(doc, "big", [](HalfedgeMesh& m) -> Check {
    MeshStorage::view(m).position[1] = glm::dvec3(7);
    throw MeshError("broken", ElementRef(EdgeId(2)));
  });
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.element, ElementRef(EdgeId(2)));
  EXPECT_EQ(doc.message.text.rfind("big: broken; " + kCause, 0), 0u);
}

}  // namespace
}  // namespace meshedit
