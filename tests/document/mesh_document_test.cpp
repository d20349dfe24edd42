// MeshDocument: apply_operation success/refusal/exception, undo/redo diffs, change counting and indexing, history
// depth, and the validation/stats caches (counted, not timed).
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/document_test_support.h"
#include "document/mesh_document.h"
#include "support/state_before_last.h"

namespace meshedit {
namespace {

using namespace document_testing;
using Cell = std::tuple<std::string, std::string, std::string, std::string>;  // element, field, before, after

std::set<Cell> cells(const std::vector<FieldChange>& changes) {
  std::set<Cell> out;
  for (const FieldChange& c : changes) out.insert({format_id(c.element), c.field, c.before, c.after});
  return out;
}

// flip(e2) on the 1x1 grid (see mesh_ops.h): a = v3, b = v0, c = v1, d = v2; f0 becomes h2 h1 h4 (v2 v1 v3),
// f1 becomes h3 h5 h0 (v1 v2 v0).
const std::set<Cell> kFlipE2 = {
    {"h0", "next", "h1", "h3"},   {"h0", "face", "f0", "f1"},     {"h1", "next", "h2", "h4"},
    {"h2", "next", "h0", "h1"},   {"h2", "vertex", "v3", "v2"},   {"h3", "next", "h4", "h5"},
    {"h3", "vertex", "v0", "v1"}, {"h4", "next", "h5", "h2"},     {"h4", "face", "f1", "f0"},
    {"h5", "next", "h3", "h0"},   {"f0", "halfedge", "h0", "h2"},
};

std::set<Cell> reversed(const std::set<Cell>& in) {
  std::set<Cell> out;
  for (const auto& [element, field, before, after] : in) out.insert({element, field, after, before});
  return out;
}

TEST(MeshDocument, FlipRecordsExactDiffAndHistory) {
  MeshDocument doc = make_document(grid_1x1(), "grid");
  const HalfedgeMesh original = doc.mesh;
  const uint64_t serial = doc.last.serial;
  const OpResult<EdgeId> r = apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); });
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_REF(r.value, E(2));
  EXPECT_EQ(doc.last.label, "flip e2");
  EXPECT_TRUE(doc.last.listed);
  EXPECT_EQ(doc.last.change_count, 11u);
  EXPECT_EQ(cells(doc.last.changes), kFlipE2);
  EXPECT_EQ(doc.last.serial, serial + 1);
  EXPECT_FALSE(doc.last.before.has_value());  // a local edit keeps its patch, not a copy of the mesh
  ASSERT_TRUE(doc.last.patch.has_value());
  EXPECT_TRUE(testing::state_before_last(doc)->same_as(original));
  EXPECT_TRUE(doc.history.can_undo());
  EXPECT_EQ(doc.history.undo_label(), "flip e2");
  EXPECT_EQ(doc.message.severity, Severity::Info);
  EXPECT_EQ(doc.message.text, "flip e2: 11 fields changed");

  // The change index answers exactly the changed cells.
  const ChangeIndex& index = doc.last.index;
  EXPECT_EQ(index.cell_count(), 11u);
  EXPECT_TRUE(index.contains(H(0), MeshField::Next));
  EXPECT_TRUE(index.contains(H(0), MeshField::Face));
  EXPECT_FALSE(index.contains(H(0), MeshField::Twin));
  EXPECT_FALSE(index.contains(H(0), MeshField::Vertex));
  EXPECT_TRUE(index.contains(H(2), MeshField::Vertex));
  EXPECT_TRUE(index.contains(F(0), MeshField::Halfedge));
  EXPECT_FALSE(index.contains(F(1), MeshField::Halfedge));
  EXPECT_FALSE(index.contains(E(2), MeshField::Halfedge));
  EXPECT_FALSE(index.contains(H(6)));
  std::vector<std::string> elements;
  for (ElementRef e : index.elements()) elements.push_back(format_id(e));
  EXPECT_EQ(elements, (std::vector<std::string>{"h0", "h1", "h2", "h3", "h4", "h5", "f0"}));
}

TEST(MeshDocument, RefusalChangesNothingButTheMessage) {
  MeshDocument doc = make_document(grid_1x1());
  const HalfedgeMesh original = doc.mesh;
  const uint64_t version = doc.mesh.version(), serial = doc.last.serial;
  const OpResult<EdgeId> r = apply_operation(doc, "flip e0", [](HalfedgeMesh& m) { return flip(m, E(0)); });
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.check.reason.empty());
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.mesh.version(), version);
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.last.serial, serial);
  EXPECT_TRUE(doc.last.label.empty());
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_EQ(doc.message.text, "flip e0: " + r.check.reason);
  EXPECT_NE(doc.message.text.find("e0"), std::string::npos);
}

TEST(MeshDocument, AnOperationThatMutatesThenRefusesIsRolledBack) {
  MeshDocument doc = make_document(grid_1x1());
  const HalfedgeMesh original = doc.mesh;
  const Check c = apply_operation(doc, "half a job", [](HalfedgeMesh& m) {
    m.set_next(H(0), H(5));
    m.new_vertex();
    return Check::no("changed my mind");
  });
  EXPECT_FALSE(c.ok);
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.mesh.version(), original.version());
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.message.text, "half a job: changed my mind");
}

TEST(MeshDocument, ExceptionsBecomeErrorsAndAreRolledBack) {
  MeshDocument doc = make_document(grid_1x1());
  const HalfedgeMesh original = doc.mesh;
  const Check c = apply_operation(doc, "explode", [](HalfedgeMesh& m) -> Check {
    m.set_twin(H(1), H(1));
    throw MeshError("h1 cannot be its own twin", H(1));
  });
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.reason, "h1 cannot be its own twin");
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "explode: h1 cannot be its own twin");
  EXPECT_REF(doc.message.element, H(1));

  const OpResult<VertexId> r = apply_operation(
      doc, "std", [](HalfedgeMesh&) -> OpResult<VertexId> { throw std::runtime_error("out of memory, pretend"); });
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.value.valid());
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "std: out of memory, pretend");
}

TEST(MeshDocument, AnOperationThatChangesNothingIsNotRecorded) {
  MeshDocument doc = make_document(grid_1x1());
  const Check c = apply_operation(doc, "look", [](HalfedgeMesh&) { return Check::yes(); });
  EXPECT_TRUE(c.ok);
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_TRUE(doc.last.label.empty());
  EXPECT_EQ(doc.message.text, "look: nothing changed");
}

TEST(MeshDocument, UndoAndRedoShowTheirOwnDiffs) {
  MeshDocument doc = make_document(grid_1x1());
  const HalfedgeMesh original = doc.mesh;
  ASSERT_TRUE(apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  const HalfedgeMesh flipped = doc.mesh;

  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(original));
  EXPECT_GT(doc.mesh.version(), flipped.version());
  EXPECT_EQ(doc.last.label, "undo flip e2");
  EXPECT_EQ(cells(doc.last.changes), reversed(kFlipE2));
  EXPECT_TRUE(testing::state_before_last(doc)->same_as(flipped));
  EXPECT_EQ(doc.message.text, "undo flip e2: 11 fields changed");
  EXPECT_TRUE(doc.last.index.contains(H(2), MeshField::Vertex));
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.history.redo_label(), "flip e2");

  ASSERT_TRUE(redo(doc));
  EXPECT_TRUE(doc.mesh.same_as(flipped));
  EXPECT_EQ(doc.last.label, "redo flip e2");
  EXPECT_EQ(cells(doc.last.changes), kFlipE2);

  EXPECT_FALSE(redo(doc));
  EXPECT_EQ(doc.message.text, "nothing to redo");
  EXPECT_EQ(doc.last.label, "redo flip e2");  // unchanged by the refusal
  ASSERT_TRUE(undo(doc));
  EXPECT_FALSE(undo(doc));
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_EQ(doc.message.text, "nothing to undo");
}

TEST(MeshDocument, SplitCreatesElementsThatUndoRemoves) {
  MeshDocument doc = make_document(grid_1x1());
  const OpResult<VertexId> r = apply_operation(doc, "split e2", [](HalfedgeMesh& m) { return split(m, E(2)); });
  ASSERT_TRUE(r.ok());
  EXPECT_REF(r.value, V(4));
  // Created elements list every field with before "-": v4 (3 fields), e5..e7 (2 each), f2 f3 (2 each),
  // h10..h15 (6 each).
  size_t created = 0;
  for (const FieldChange& c : doc.last.changes) created += c.before == "-";
  EXPECT_EQ(created, 3u + 3 * 2 + 2 * 2 + 6 * 6);
  EXPECT_TRUE(doc.last.index.contains(V(4), MeshField::Position));
  EXPECT_TRUE(doc.last.index.contains(H(15), MeshField::Alive));
  ASSERT_TRUE(undo(doc));
  EXPECT_EQ(doc.mesh.vertex_capacity(), 4u);
  EXPECT_FALSE(doc.mesh.alive(V(4)));
  for (const FieldChange& c : doc.last.changes)
    if (c.element == ElementRef(V(4))) {
      EXPECT_EQ(c.after, "-");
    }
}

TEST(MeshDocument, CountChangesAgreesWithDiff) {
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(3, 2));
  const HalfedgeMesh before = grid;
  ASSERT_TRUE(flip(grid, E(2)).ok());
  EXPECT_EQ(count_changes(before, grid, 1000), diff(before, grid).size());
  ASSERT_TRUE(split(grid, E(7)).ok());
  EXPECT_EQ(count_changes(before, grid, 1000), diff(before, grid).size());
  ASSERT_TRUE(collapse(grid, E(3)).ok());
  EXPECT_EQ(count_changes(before, grid, 1000), diff(before, grid).size());
  ASSERT_TRUE(loop_subdivide(grid).ok);
  const size_t all = diff(before, grid).size();
  EXPECT_EQ(count_changes(before, grid, all), all);
  EXPECT_EQ(count_changes(grid, before, all), all);  // swapped: slots only in `before`
  EXPECT_GT(count_changes(before, grid, 10), 10u);   // stops early, but says "more"
  EXPECT_EQ(count_changes(grid, grid, 0), 0u);
}

TEST(MeshDocument, HugeDiffsAreCountedNotListed) {
  DocumentLimits limits;
  limits.max_listed_changes = 50;
  MeshDocument doc = make_document(build_halfedge_mesh(make_grid(4, 4)), "", limits);
  ASSERT_TRUE(apply_operation(doc, "Loop subdivision", [](HalfedgeMesh& m) { return loop_subdivide(m); }).ok);
  EXPECT_FALSE(doc.last.listed);
  EXPECT_TRUE(doc.last.changes.empty());
  EXPECT_GT(doc.last.change_count, 50u);
  EXPECT_EQ(doc.last.index.cell_count(), 0u);
  EXPECT_EQ(doc.message.text, "Loop subdivision: more than 50 fields changed (too many to list)");
  EXPECT_TRUE(doc.history.can_undo());
  // A small change afterwards is listed again.
  ASSERT_TRUE(apply_operation(doc, "flip e30", [](HalfedgeMesh& m) { return flip(m, E(30)); }).ok());
  // 10 halfedge fields, and both faces' halfedge fields (flip sets them to h0 and h1 of the edge).
  EXPECT_TRUE(doc.last.listed);
  EXPECT_EQ(doc.last.changes.size(), 12u);
  EXPECT_EQ(doc.last.change_count, 12u);
}

// The document copies the mesh into last.before only for the renderer's in-place update of a listed whole-mesh change.
// A whole-mesh change too long to list, its undo and its redo keep no copy (on a big mesh, undo of L copied the
// subdivided mesh for nothing: ~1 s at 4M faces), and neither does a local edit (its patch is enough: the first edit
// after opening or after L copied the whole mesh, 44 ms at 1M faces, and kept a second mesh in memory).
TEST(MeshDocument, OnlyAListedWholeMeshChangeKeepsACopyOfTheStateBefore) {
  DocumentLimits limits;
  limits.max_listed_changes = 50;
  const HalfedgeMesh grid = build_halfedge_mesh(make_grid(4, 4));
  MeshDocument doc = make_document(grid, "", limits);
  ASSERT_TRUE(apply_operation(doc, "Loop subdivision", [](HalfedgeMesh& m) { return loop_subdivide(m); }).ok);
  ASSERT_FALSE(doc.last.listed);
  EXPECT_FALSE(doc.last.before.has_value());
  const HalfedgeMesh subdivided = doc.mesh;
  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(grid));
  EXPECT_FALSE(doc.last.listed);
  EXPECT_FALSE(doc.last.before.has_value());
  EXPECT_EQ(doc.message.text, "undo Loop subdivision: more than 50 fields changed (too many to list)");
  ASSERT_TRUE(redo(doc));
  EXPECT_TRUE(doc.mesh.same_as(subdivided));
  EXPECT_FALSE(doc.last.before.has_value());
  // The flip after it: listed, its patch gives the exact state before, and the same cells a plain diff gives.
  ASSERT_TRUE(apply_operation(doc, "flip e30", [](HalfedgeMesh& m) { return flip(m, E(30)); }).ok());
  EXPECT_FALSE(doc.last.before.has_value());
  ASSERT_TRUE(doc.last.patch.has_value());
  EXPECT_TRUE(testing::state_before_last(doc)->same_as(subdivided));
  EXPECT_EQ(cells(doc.last.changes), cells(diff(subdivided, doc.mesh)));
  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(subdivided));
  // A whole-mesh change that is listed keeps its state before, as the renderer's in-place update needs.
  MeshDocument small = make_document(grid);
  ASSERT_TRUE(apply_operation(small, "Loop subdivision", [](HalfedgeMesh& m) { return loop_subdivide(m); }).ok);
  ASSERT_TRUE(small.last.listed);
  ASSERT_TRUE(small.last.before.has_value());
  EXPECT_TRUE(small.last.before->same_as(grid));
  ASSERT_TRUE(undo(small));
  ASSERT_TRUE(small.last.before.has_value());
  EXPECT_TRUE(small.last.before->same_as(subdivided));
}

TEST(MeshDocument, HistoryDepthFollowsTheMemoryBudget) {
  DocumentLimits limits;
  limits.history_budget_bytes = 1;  // at least 4 steps are always kept
  MeshDocument doc = make_document(build_halfedge_mesh(make_grid(3, 3)), "", limits);
  for (uint32_t i = 0; i < 6; ++i) {
    ASSERT_TRUE(apply_operation(doc, "move v" + std::to_string(i), [i](HalfedgeMesh& m) {
                  m.set_position(V(i), glm::dvec3(9.0));
                  return Check::yes();
                }).ok);
  }
  EXPECT_EQ(doc.history.undo_depth(), 4u);
}

TEST(MeshDocument, LocalEditsKeepADeepHistoryWhateverTheMeshSize) {
  // A budget of two meshes: 20 local edits are small patches and all stay (a snapshot history would keep 4);
  // two subdivisions are snapshots, and the second alone is over the budget, so only the 4 newest steps stay.
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(6, 6));
  DocumentLimits limits;
  limits.history_budget_bytes = 2 * grid.memory_bytes();
  MeshDocument doc = make_document(std::move(grid), "", limits);
  for (uint32_t i = 0; i < 20; ++i) {
    ASSERT_TRUE(apply_operation(doc, "move v" + std::to_string(i), [i](HalfedgeMesh& m) {
                  m.set_position(V(i), glm::dvec3(i, 9.0, 0.0));
                  return Check::yes();
                }).ok);
  }
  EXPECT_EQ(doc.history.undo_depth(), 20u);
  for (const char* label : {"loop 1", "loop 2"}) {
    ASSERT_TRUE(apply_operation(doc, label, [](HalfedgeMesh& m) { return loop_subdivide(m, LoopWeights::Loop); }).ok);
  }
  EXPECT_EQ(doc.history.undo_depth(), History::kMinDepth);
  for (const char* label : {"loop 2", "loop 1", "move v19", "move v18"}) {
    EXPECT_EQ(doc.history.undo_label(), label);
    ASSERT_TRUE(undo(doc));
  }
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.mesh.num_faces(), 72u);  // the grid again, with v0..v17 still moved
  EXPECT_EQ(doc.mesh.position(V(17)), glm::dvec3(17.0, 9.0, 0.0));
  EXPECT_NE(doc.mesh.position(V(18)).y, 9.0);
}

TEST(MeshDocument, ReplaceMeshStartsAfresh) {
  MeshDocument doc = make_document(grid_1x1(), "a.obj");
  ASSERT_TRUE(apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  const uint64_t generation = doc.generation, serial = doc.last.serial;
  replace_mesh(doc, build_halfedge_mesh(make_tetrahedron()), "b.obj");
  EXPECT_EQ(doc.path, "b.obj");
  EXPECT_EQ(doc.generation, generation + 1);
  EXPECT_GT(doc.last.serial, serial);
  EXPECT_TRUE(doc.last.label.empty());
  EXPECT_TRUE(doc.last.changes.empty());
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.message.text, "opened b.obj: 4 vertices, 4 faces");
}

TEST(MeshDocument, ValidationRunsOncePerMeshState) {
  MeshDocument doc = make_document(grid_1x1());
  EXPECT_FALSE(validation_is_current(doc));
  EXPECT_TRUE(cached_validation(doc).ok());
  for (int frame = 0; frame < 10; ++frame) cached_validation(doc);
  EXPECT_EQ(doc.validation.computations, 1u);
  EXPECT_TRUE(validation_is_current(doc));

  apply_operation(doc, "flip e0", [](HalfedgeMesh& m) { return flip(m, E(0)); });  // refused: same state
  cached_validation(doc);
  EXPECT_EQ(doc.validation.computations, 1u);

  ASSERT_TRUE(apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  EXPECT_FALSE(validation_is_current(doc));
  cached_validation(doc);
  cached_validation(doc);
  EXPECT_EQ(doc.validation.computations, 2u);

  ASSERT_TRUE(undo(doc));
  cached_validation(doc);
  EXPECT_EQ(doc.validation.computations, 3u);

  // A broken mesh: the cache reports the problem.
  ASSERT_TRUE(apply_operation(doc, "break", [](HalfedgeMesh& m) {
                m.set_twin(H(0), H(1));
                return Check::yes();
              }).ok);
  const ValidationReport& report = cached_validation(doc);
  EXPECT_FALSE(report.ok());
  EXPECT_EQ(doc.validation.computations, 4u);

  // Replacing the mesh invalidates the cache even if the version counters agree.
  HalfedgeMesh other = grid_1x1();
  replace_mesh(doc, std::move(other), "");
  EXPECT_FALSE(validation_is_current(doc));
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_EQ(doc.validation.computations, 5u);
}

// After a state the cache found clean, a local change (an operation, an undo, a redo) is validated from its patch
// alone; the answers are the whole-mesh check's, and a broken change is still reported with its element.
TEST(MeshDocument, ValidatesALocalChangeFromItsPatch) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 4)));
  ASSERT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.clean);
  EXPECT_FALSE(doc.validation.value.from_patch);

  ASSERT_TRUE(apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  ASSERT_NE(cached_validation_if_cheap(doc), nullptr);
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.from_patch);
  ASSERT_TRUE(apply_operation(doc, "split e7", [](HalfedgeMesh& m) { return split(m, E(7)); }).ok());
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.from_patch);
  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.from_patch);
  ASSERT_TRUE(redo(doc));
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.from_patch);

  const HalfedgeId twin = doc.mesh.twin(H(0));
  ASSERT_TRUE(apply_operation(doc, "break", [](HalfedgeMesh& m) {
                m.set_twin(H(0), H(1));
                return Check::yes();
              }).ok);
  EXPECT_EQ(cached_validation_if_cheap(doc), nullptr);  // its patch shows it broke the mesh: the report needs it all
  const ValidationReport expected = validate_without_shortcut(doc.mesh);
  const ValidationReport& report = cached_validation(doc);
  ASSERT_FALSE(report.ok());
  EXPECT_FALSE(doc.validation.value.clean);
  EXPECT_FALSE(doc.validation.value.from_patch);
  EXPECT_EQ(report.total, expected.total);
  EXPECT_EQ(report.violations.front().element, expected.violations.front().element);
  EXPECT_EQ(report.violations.front().message, expected.violations.front().message);

  // From a broken state, the next change needs the whole mesh again; after it, patches serve again.
  ASSERT_TRUE(apply_operation(doc, "mend", [&](HalfedgeMesh& m) {
                m.set_twin(H(0), twin);
                return Check::yes();
              }).ok);
  EXPECT_EQ(cached_validation_if_cheap(doc), nullptr);
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_FALSE(doc.validation.value.from_patch);
  ASSERT_TRUE(apply_operation(doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, E(9)); }).ok());
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_TRUE(doc.validation.value.from_patch);
}

// A patch only tells from the state it started at: a change nobody validated breaks the chain.
TEST(MeshDocument, ValidatesTheWholeMeshAfterAnUnvalidatedState) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 4)));
  ASSERT_TRUE(cached_validation(doc).ok());
  ASSERT_TRUE(apply_operation(doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  ASSERT_TRUE(apply_operation(doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, E(9)); }).ok());
  EXPECT_EQ(cached_validation_if_cheap(doc), nullptr);
  EXPECT_TRUE(cached_validation(doc).ok());
  EXPECT_FALSE(doc.validation.value.from_patch);
  EXPECT_EQ(doc.validation.computations, 2u);
}

TEST(MeshDocument, StatsAreCachedToo) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 4)));
  EXPECT_EQ(cached_stats(doc).euler_characteristic, 0);
  ASSERT_TRUE(cached_stats(doc).genus.has_value());
  EXPECT_EQ(*cached_stats(doc).genus, 1);
  EXPECT_EQ(doc.stats.computations, 1u);
  ASSERT_TRUE(apply_operation(doc, "split e0", [](HalfedgeMesh& m) { return split(m, E(0)); }).ok());
  EXPECT_EQ(cached_stats(doc).vertices, 25u);
  EXPECT_EQ(doc.stats.computations, 2u);
}

TEST(MeshDocument, FieldNamesRoundTrip) {
  for (int i = 0; i < kMeshFieldCount; ++i) {
    const auto field = static_cast<MeshField>(i);
    EXPECT_EQ(parse_field(field_name(field)), field);
  }
  EXPECT_FALSE(parse_field("nexts").has_value());
  EXPECT_FALSE(parse_field("").has_value());
}

}  // namespace
}  // namespace meshedit
