// plan_update against the full build, on the CPU: after every step of long random runs of flips, splits, collapses,
// undos, redos, now and then a Loop subdivision, and raw pointer writes (which break the mesh), the patched slot
// arrays equal build_slot_geometry of the new state byte for byte (a step with no patch rebuilds, as the renderer
// does). A flip on a big mesh rewrites a few dozen slots. The drawn set of the slot layout equals
// build_mesh_geometry's. Every step an edit's change journal can follow is also planned with the state before read
// through its patch (StateBefore, as the window does), which must give the same slots and the same state.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/primitives.h"
#include "quad_torus.h"
#include "render/incremental_update.h"
#include "update_test_support.h"

namespace meshedit {
namespace {

using testing::changed_elements;
using testing::same_bytes;

// The CPU mirror of a renderer: slot arrays and arrows kept up to date by patches, rebuilt when there is none.
struct Mirror {
  SlotGeometry g;
  std::vector<EdgeSegment> arrows;
  SlotState state;
  size_t patches = 0, rebuilds = 0, last_slots = 0, through_patches = 0;

  explicit Mirror(const HalfedgeMesh& mesh) { rebuild(mesh); }
  void rebuild(const HalfedgeMesh& mesh) {
    g = build_slot_geometry(mesh);
    arrows = build_slot_arrows(mesh);
    state = slot_state(mesh, g);
    ++rebuilds;
  }
  // With `edit`, the patch of the change, the plan is also made through it, and must agree with the copy's.
  void update(const HalfedgeMesh& before, const HalfedgeMesh& after, const MeshPatch* edit = nullptr) {
    const std::vector<ElementRef> changed = changed_elements(before, after);
    std::optional<SlotPatch> through_edit;
    SlotState state_through_edit = state;
    if (edit != nullptr) {
      std::string why;
      through_edit = plan_update(StateBefore(after, *edit), after, changed, state_through_edit, true, why);
    }
    std::string why;
    const std::optional<SlotPatch> patch = plan_update(before, after, changed, state, true, why);
    if (edit != nullptr) {
      ++through_patches;
      EXPECT_EQ(through_edit.has_value(), patch.has_value()) << why;
      if (through_edit && patch) {
        SlotGeometry g_through = g;
        std::vector<EdgeSegment> arrows_through = arrows;
        apply_patch(g_through, &arrows_through, *through_edit);
        SlotGeometry g_copy = g;
        std::vector<EdgeSegment> arrows_copy = arrows;
        apply_patch(g_copy, &arrows_copy, *patch);
        testing::expect_same_slots(g_through, g_copy);
        EXPECT_TRUE(same_bytes(arrows_through, arrows_copy));
        EXPECT_EQ(through_edit->slots(), patch->slots());
        EXPECT_TRUE(state_through_edit.references == state.references);
        EXPECT_EQ(state_through_edit.boundary_edges, state.boundary_edges);
        EXPECT_EQ(state_through_edit.extra_first, state.extra_first);
      }
    }
    if (!patch) {
      rebuild(after);
      return;
    }
    apply_patch(g, &arrows, *patch);
    last_slots = patch->slots();
    ++patches;
  }
};

void expect_equal(const Mirror& m, const HalfedgeMesh& mesh, const std::string& step) {
  SCOPED_TRACE(step);
  const SlotGeometry full = build_slot_geometry(mesh);
  testing::expect_same_slots(m.g, full);
  EXPECT_TRUE(same_bytes(m.arrows, build_slot_arrows(mesh)));
  EXPECT_TRUE(m.state.references == MeshReferences::count(mesh));
  EXPECT_EQ(m.state.boundary_edges, full.boundary_edges);
  // The box never shrinks: it holds the full build's.
  if (!full.bounds.empty()) {
    EXPECT_LE(m.g.bounds.min.x, full.bounds.min.x);
    EXPECT_GE(m.g.bounds.max.z, full.bounds.max.z);
  }
}

// A random run: mostly core operations and history steps, now and then a raw write that breaks the mesh.
struct RunCounts {
  size_t patches = 0, rebuilds = 0, through_patches = 0;
};

RunCounts random_run(HalfedgeMesh mesh, uint32_t seed, int steps, bool raw_writes) {
  std::mt19937 rng(seed);
  History history(64);
  Mirror mirror(mesh);
  for (int step = 0; step < steps; ++step) {
    const HalfedgeMesh before = mesh;
    constexpr int kLoop = 100;  // now and then on a small mesh: every element changes, a big patch
    const int what = rng() % 80 == 0 && mesh.num_faces() < 600 ? kLoop : int(rng() % (raw_writes ? 9 : 7));
    std::string label;
    const EdgeId e(uint32_t(rng() % std::max<uint32_t>(mesh.edge_capacity(), 1)));
    ChangeJournal journal(mesh);  // falls back to a snapshot for Loop and for the history's assignments
    switch (what) {
      case kLoop:
        label = "Loop subdivision";
        if (loop_subdivide(mesh)) history.record(label, before);
        break;
      case 0:
      case 1:
        label = "flip";
        if (flip(mesh, e)) history.record(label, before);
        break;
      case 2:
        label = "split";
        if (split(mesh, e)) history.record(label, before);
        break;
      case 3:
        label = "collapse";
        if (collapse(mesh, e)) history.record(label, before);
        break;
      case 4:
      case 5:
        label = "undo";
        history.undo(mesh);
        break;
      case 6:
        label = "redo";
        history.redo(mesh);
        break;
      case 7: {
        label = "raw pointer write";
        const HalfedgeId h(uint32_t(rng() % mesh.halfedge_capacity()));
        const HalfedgeId to(uint32_t(rng() % mesh.halfedge_capacity()));
        switch (rng() % 4) {
          case 0: mesh.set_next(h, to); break;
          case 1: mesh.set_twin(h, to); break;
          case 2: mesh.set_vertex(h, VertexId(uint32_t(rng() % mesh.vertex_capacity()))); break;
          default: mesh.set_face(h, FaceId::face(uint32_t(rng() % mesh.face_capacity()))); break;
        }
        history.record(label, before);
        break;
      }
      default: {
        label = "raw move or delete";
        const VertexId v(uint32_t(rng() % mesh.vertex_capacity()));
        if (rng() % 3 == 0) mesh.delete_element(v);
        else mesh.set_position(v, mesh.position(v) + glm::dvec3(0.01, -0.02, 0.03));
        history.record(label, before);
        break;
      }
    }
    journal.detach();
    if (mesh.version() == before.version()) continue;
    std::optional<MeshPatch> edit;
    if (!journal.has_snapshot() && !journal.state_before_lost()) edit = make_patch(journal, mesh);
    mirror.update(before, mesh, edit ? &*edit : nullptr);
    expect_equal(mirror, mesh, "step " + std::to_string(step) + ": " + label);
    if (::testing::Test::HasFailure()) break;
  }
  return {mirror.patches, mirror.rebuilds - 1, mirror.through_patches};
}

TEST(IncrementalUpdate, LocalEditsUndoAndRedoGiveTheFullBuild) {
  const RunCounts counts = random_run(build_halfedge_mesh(make_torus(12, 10)), 1, 400, false);
  EXPECT_GT(counts.patches, 250u);  // valid meshes: every step is a patch
  EXPECT_EQ(counts.rebuilds, 0u);
  EXPECT_GT(counts.through_patches, 150u);  // the operations (undo and redo assign snapshots here)
}

TEST(IncrementalUpdate, MeshesWithBoundaryGiveTheFullBuild) {
  const RunCounts counts = random_run(build_halfedge_mesh(make_grid(8, 7)), 2, 400, false);
  EXPECT_GT(counts.patches, 250u);
  EXPECT_EQ(counts.rebuilds, 0u);
}

TEST(IncrementalUpdate, BrokenMeshesGiveTheFullBuild) {
  RunCounts all;
  for (uint32_t seed = 3; seed < 9; ++seed) {
    const RunCounts counts = random_run(build_halfedge_mesh(make_grid(6, 5)), seed, 300, true);
    all.patches += counts.patches;
    all.through_patches += counts.through_patches;
    all.rebuilds += counts.rebuilds;
  }
  const RunCounts torus = random_run(build_halfedge_mesh(make_torus(8, 6)), 11, 400, true);
  // Both kinds happen: certificates pass where the breakage is far, and fail near it.
  EXPECT_GT(all.patches + torus.patches, 100u);
  EXPECT_GT(all.rebuilds + torus.rebuilds, 10u);
  EXPECT_GT(all.through_patches + torus.through_patches, 600u);
  std::printf("broken meshes: %zu patches, %zu rebuilds, %zu planned through the edit too\n",
              all.patches + torus.patches, all.rebuilds + torus.rebuilds, all.through_patches + torus.through_patches);
}

TEST(IncrementalUpdate, PolygonsArePatchedWhileTheirTriangleCountsStay) {
  // The core's operations want triangles; on quads it is scripts that move vertices (the quads keep their two
  // triangles: patched in place) and rewire pointers (a quad that loses or gains a corner: rebuilt).
  const RunCounts quads = random_run(build_halfedge_mesh(quad_torus(9, 7)), 5, 300, true);
  EXPECT_GT(quads.patches, 20u);
  EXPECT_GT(quads.rebuilds, 20u);
  random_run(build_halfedge_mesh(make_cube_quads()), 6, 200, true);
}

TEST(IncrementalUpdate, AFlipOnABigMeshRewritesAFewSlots) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(100000));
  Mirror mirror(mesh);
  const HalfedgeMesh before = mesh;
  ASSERT_TRUE(flip(mesh, EdgeId(12345)));
  mirror.update(before, mesh);
  EXPECT_EQ(mirror.patches, 1u);
  EXPECT_LE(mirror.last_slots, 40u);
  expect_equal(mirror, mesh, "flip e12345");
}

TEST(SlotGeometry, DrawsWhatTheCompactBuildDraws) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(3, 2));
  mesh.set_next(HalfedgeId(4), HalfedgeId(0));  // breaks f1
  mesh.set_position(VertexId(7), glm::dvec3(NAN, 0.0, 0.0));
  const MeshGeometry compact = build_mesh_geometry(mesh);
  const SlotGeometry slots = build_slot_geometry(mesh);
  EXPECT_EQ(slots.counts.triangles, compact.triangle_count());
  EXPECT_EQ(slots.counts.skipped_faces, compact.skipped_faces.size());
  EXPECT_EQ(slots.counts.edges, compact.edges.size());
  EXPECT_EQ(slots.counts.skipped_edges, compact.skipped_edges.size());
  EXPECT_EQ(slots.counts.vertices, compact.points.size());
  for (size_t t = 0; t < compact.triangle_count(); ++t) {
    const uint32_t f = compact.triangle_faces[t];
    EXPECT_EQ(slots.triangles[3 * f], compact.triangle_corners[3 * t]);
    EXPECT_EQ(slots.triangles[3 * f + 1], compact.triangle_corners[3 * t + 1]);
    EXPECT_EQ(slots.triangles[3 * f + 2], compact.triangle_corners[3 * t + 2]);
  }
  for (const EdgeSegment& s : compact.edges) EXPECT_EQ(std::memcmp(&slots.edges[s.edge], &s, sizeof s), 0);
  for (const VertexPoint& p : compact.points) EXPECT_EQ(std::memcmp(&slots.points[p.vertex], &p, sizeof p), 0);
}

}  // namespace
}  // namespace meshedit
