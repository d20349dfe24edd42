// MeshDocument on its journaled path: random edits, undos and redos give the same meshes, version() numbers and
// `last` diffs as the plain snapshot path (a reference History of whole snapshots run alongside); refused and
// throwing operations leave mesh, history and `last` untouched; whole-mesh passes and huge scripts fall back to
// snapshots and still undo and redo exactly; the state before the last change (its patch, or last.before) is always
// exact.
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "document/mesh_document.h"
#include "support/diff_expect.h"
#include "support/random_edits.h"
#include "support/state_before_last.h"

namespace meshedit {
namespace {

// `last` describes the change from `before` to the document's mesh: its patch (or last.before) gives that exact state.
void expect_last_change(const MeshDocument& doc, const HalfedgeMesh& before) {
  const std::optional<HalfedgeMesh> state = testing::state_before_last(doc);
  ASSERT_TRUE(state.has_value());
  EXPECT_TRUE(state->same_as(before));
  ASSERT_TRUE(doc.last.version_before.has_value());
  EXPECT_EQ(*doc.last.version_before, before.version());
  EXPECT_EQ(doc.last.version_after, doc.mesh.version());
  const std::vector<FieldChange> expected = diff(before, doc.mesh);
  testing::expect_same_diff(doc.last.changes, expected);
  EXPECT_EQ(doc.last.change_count, expected.size());
  EXPECT_EQ(doc.message.text, doc.last.label + ": " + std::to_string(expected.size()) +
                                  (expected.size() == 1 ? " field" : " fields") + " changed");
}

TEST(DocumentJournal, RandomEditsUndoRedoMatchTheSnapshotPath) {
  for (uint32_t seed = 1; seed <= 25; ++seed) {
    SCOPED_TRACE(seed);
    MeshDocument doc = make_document(testing::edited_torus(seed));
    HalfedgeMesh reference = doc.mesh;  // edited alongside, undone with whole snapshots
    History reference_history(doc.history.undo_depth() + 256);
    std::mt19937 random(seed);
    for (int step = 0; step < 40; ++step) {
      SCOPED_TRACE(step);
      const HalfedgeMesh before = doc.mesh;
      const uint32_t action = random() % 4;
      if (action == 0 && doc.history.can_undo()) {
        ASSERT_TRUE(undo(doc));
        ASSERT_TRUE(reference_history.undo(reference));
      } else if (action == 1 && doc.history.can_redo()) {
        ASSERT_TRUE(redo(doc));
        ASSERT_TRUE(reference_history.redo(reference));
      } else {
        std::mt19937 same_edit = random;
        apply_operation(doc, "edit", [&](HalfedgeMesh& m) {
          testing::random_edit_or_write(m, random);
          return Check::yes();
        });
        const HalfedgeMesh reference_before = reference;
        testing::random_edit_or_write(reference, same_edit);
        if (reference.version() != reference_before.version()) reference_history.record("edit", reference_before);
        if (doc.mesh.version() == before.version()) {
          EXPECT_EQ(doc.message.text, "edit: nothing changed");
          continue;
        }
      }
      ASSERT_TRUE(doc.mesh.same_as(reference));
      EXPECT_EQ(doc.mesh.version(), reference.version());
      EXPECT_GT(doc.mesh.version(), before.version());
      EXPECT_EQ(doc.mesh.num_vertices(), reference.num_vertices());
      EXPECT_EQ(doc.mesh.num_halfedges(), reference.num_halfedges());
      EXPECT_EQ(doc.mesh.num_edges(), reference.num_edges());
      EXPECT_EQ(doc.mesh.num_faces(), reference.num_faces());
      EXPECT_EQ(doc.mesh.num_boundaries(), reference.num_boundaries());
      EXPECT_EQ(doc.history.undo_depth(), reference_history.undo_depth());
      EXPECT_EQ(doc.history.can_redo(), reference_history.can_redo());
      expect_last_change(doc, before);
    }
  }
}

// An operation that writes, appends and deletes, then fails in the given way.
enum class Failure { Refuse, ThrowMeshError, ThrowStd };
Check write_then_fail(HalfedgeMesh& m, Failure failure) {
  m.set_next(HalfedgeId(0), HalfedgeId(9));
  m.set_position(VertexId(1), {7, 7, 7});
  m.delete_element(EdgeId(2));
  const VertexId v = m.new_vertex();
  m.set_halfedge(v, HalfedgeId(3));
  switch (failure) {
    case Failure::Refuse: return Check::no("not today");
    case Failure::ThrowMeshError: throw MeshError("broken", ElementRef(v));
    case Failure::ThrowStd: throw std::runtime_error("boom");
  }
  return Check::yes();
}

TEST(DocumentJournal, RefusedAndThrowingOperationsLeaveEverythingAsItWas) {
  for (const Failure failure : {Failure::Refuse, Failure::ThrowMeshError, Failure::ThrowStd}) {
    MeshDocument doc = make_document(testing::edited_torus(7));
    std::mt19937 random(7);
    for (int i = 0; i < 3; ++i) {
      apply_operation(doc, "edit", [&](HalfedgeMesh& m) {
        testing::random_edit_or_write(m, random);
        return Check::yes();
      });
    }
    const HalfedgeMesh mesh = doc.mesh;
    const uint64_t serial = doc.last.serial;
    const HalfedgeMesh last_before = testing::state_before_last(doc).value();
    const size_t changes = doc.last.changes.size(), depth = doc.history.undo_depth();
    const Check check = apply_operation(doc, "bad", [&](HalfedgeMesh& m) { return write_then_fail(m, failure); });
    EXPECT_FALSE(check.ok);
    EXPECT_TRUE(doc.mesh.same_as(mesh));
    EXPECT_EQ(doc.mesh.version(), mesh.version());
    EXPECT_EQ(doc.mesh.num_vertices(), mesh.num_vertices());
    EXPECT_EQ(doc.mesh.num_edges(), mesh.num_edges());
    EXPECT_EQ(doc.history.undo_depth(), depth);
    EXPECT_EQ(doc.last.serial, serial);
    EXPECT_EQ(doc.last.changes.size(), changes);
    const std::optional<HalfedgeMesh> state = testing::state_before_last(doc);
    ASSERT_TRUE(state.has_value());
    EXPECT_TRUE(state->same_as(last_before));
    // The next edit still sees the right state before it.
    ASSERT_TRUE(apply_operation(doc, "edit", [](HalfedgeMesh& m) {
                  m.set_position(VertexId(0), {1, 2, 3});
                  return Check::yes();
                }).ok);
    expect_last_change(doc, mesh);
    ASSERT_TRUE(undo(doc));
    EXPECT_TRUE(doc.mesh.same_as(mesh));
  }
}

// Runs `op` through the document and checks it was kept as a snapshot that undoes and redoes exactly, with the
// edits around it still exact.
template <class Op>
void expect_snapshot_entry(MeshDocument& doc, Op&& op) {
  ASSERT_TRUE(apply_operation(doc, "flip", [](HalfedgeMesh& m) { return flip(m, EdgeId(4)); }).ok());
  const HalfedgeMesh before = doc.mesh;
  ASSERT_TRUE(apply_operation(doc, "big", op).ok);
  EXPECT_EQ(doc.history.undo_patch(), nullptr);
  EXPECT_FALSE(doc.last.patch.has_value());
  expect_last_change(doc, before);
  const HalfedgeMesh after = doc.mesh;
  ASSERT_TRUE(apply_operation(doc, "move", [](HalfedgeMesh& m) {
                m.set_position(VertexId(0), {0.25, 0, 0});
                return Check::yes();
              }).ok);
  EXPECT_NE(doc.history.undo_patch(), nullptr);
  expect_last_change(doc, after);
  const HalfedgeMesh moved = doc.mesh;
  // Each step: the mesh it should give, and `last` from the state just before it.
  auto step = [&](bool forward, const HalfedgeMesh& expected) {
    const HalfedgeMesh prior = doc.mesh;
    ASSERT_TRUE(forward ? redo(doc) : undo(doc));
    EXPECT_TRUE(doc.mesh.same_as(expected));
    EXPECT_GT(doc.mesh.version(), prior.version());
    expect_last_change(doc, prior);
  };
  step(false, after);
  step(false, before);
  step(true, after);
  step(true, moved);
  step(false, after);
}

TEST(DocumentJournal, LoopSubdivisionIsKeptAsASnapshot) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  expect_snapshot_entry(doc, [](HalfedgeMesh& m) { return loop_subdivide(m); });
}

TEST(DocumentJournal, AScriptPastTheLogCapIsKeptAsASnapshot) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  expect_snapshot_entry(doc, [](HalfedgeMesh& m) {
    for (uint32_t i = 0; i < 10000; ++i) m.set_position(VertexId(i % m.vertex_capacity()), glm::dvec3(i, 0.5, 1));
    return Check::yes();
  });
}

TEST(DocumentJournal, AssigningTheWholeMeshIsKeptAsASnapshot) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  expect_snapshot_entry(doc, [&](HalfedgeMesh& m) {
    m = cube;
    m.bump_version_above(1000);
    return Check::yes();
  });
}

// An operation that assigns a mesh whose version() happens to equal the document's: the contents changed, so it is
// a change (recorded, undoable) and the version moves on, or caches keyed by version would describe the old mesh.
TEST(DocumentJournal, AssigningAMeshWithTheSameVersionIsAChange) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  ASSERT_TRUE(cached_validation(doc).ok());
  const HalfedgeMesh before = doc.mesh;
  HalfedgeMesh broken = build_halfedge_mesh(make_cube());
  broken.set_twin(HalfedgeId(0), HalfedgeId(0));
  MeshStorage::set_versions(broken, doc.mesh.version(), MeshStorage::proven_version(broken));
  const size_t fields = diff(before, broken).size();

  ASSERT_TRUE(apply_operation(doc, "assign", [&](HalfedgeMesh& m) {
                m = broken;
                return Check::yes();
              }).ok);
  EXPECT_TRUE(doc.mesh.same_as(broken));
  EXPECT_GT(doc.mesh.version(), before.version());
  EXPECT_EQ(doc.message.text, "assign: " + std::to_string(fields) + " fields changed");
  EXPECT_EQ(doc.history.undo_label(), "assign");
  expect_last_change(doc, before);
  EXPECT_FALSE(validation_is_current(doc));
  EXPECT_FALSE(cached_validation(doc).ok());  // the broken cube's report, not the torus's
  EXPECT_EQ(doc.validation.computations, 2u);

  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(before));
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_EQ(doc.validation.computations, 3u);
}

// Assigning a mesh with the same contents changes nothing, whatever version it brings: not recorded, and the mesh
// keeps its own version.
TEST(DocumentJournal, AssigningTheSameContentsChangesNothing) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  ASSERT_TRUE(apply_operation(doc, "flip", [](HalfedgeMesh& m) { return flip(m, EdgeId(4)); }).ok());
  const HalfedgeMesh mesh = doc.mesh;
  const uint64_t serial = doc.last.serial;
  HalfedgeMesh same = doc.mesh;
  same.bump_version_above(doc.mesh.version() + 10);
  ASSERT_TRUE(apply_operation(doc, "assign", [&](HalfedgeMesh& m) {
                m = same;
                return Check::yes();
              }).ok);
  EXPECT_EQ(doc.message.text, "assign: nothing changed");
  EXPECT_EQ(doc.mesh.version(), mesh.version());
  EXPECT_EQ(doc.history.undo_label(), "flip");
  EXPECT_EQ(doc.history.undo_depth(), 1u);
  EXPECT_EQ(doc.last.serial, serial);
}

TEST(DocumentJournal, LocalEditsAreKeptAsPatches) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)));
  ASSERT_TRUE(apply_operation(doc, "split", [](HalfedgeMesh& m) { return split(m, EdgeId(3)); }).ok());
  EXPECT_NE(doc.history.undo_patch(), nullptr);
  EXPECT_TRUE(doc.last.patch.has_value());
}

}  // namespace
}  // namespace meshedit
