// The check of one edit (core/patch_check.h) gives exactly the whole-mesh quick check's answer after the edit, on
// every edit the core's operations make and on random pointer writes, deletions and new elements; it refuses a patch
// that does not end in the mesh it is given.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/patch_check.h"
#include "core/primitives.h"
#include "core/quick_check.h"
#include "core/validate.h"
#include "support/journaled_edit.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

using testing::patch_of;

HalfedgeMesh fixture(uint32_t seed) {
  switch (seed % 4) {
    case 0: return build_halfedge_mesh(make_grid(4, 3));  // a boundary
    case 1: return testing::edited_torus(seed);           // dead slots, irregular valences
    case 2: return build_halfedge_mesh(make_cube());      // quads
    default: return build_halfedge_mesh(make_torus(6, 5));
  }
}

// Writes that keep most of the mesh consistent, so that a break shows in few rules (or none): deleting one element,
// swapping two halfedges' twins, nexts, vertices or faces, or moving an element's halfedge along its own cycle or fan
// (which keeps the mesh valid).
void rewire_randomly(HalfedgeMesh& m, std::mt19937& random) {
  const auto live_halfedge = [&] {
    HalfedgeId h(random() % m.halfedge_capacity());
    while (!m.alive(h)) h = HalfedgeId((h.index + 1) % m.halfedge_capacity());
    return h;
  };
  const HalfedgeId a = live_halfedge(), b = live_halfedge();
  switch (random() % 9) {
    case 0: m.delete_element(m.vertex(a)); break;
    case 1: m.delete_element(m.face(a)); break;
    case 2: m.delete_element(a); break;
    case 3: {
      const HalfedgeId ta = m.twin(a), tb = m.twin(b);
      m.set_twin(a, tb);
      m.set_twin(tb, a);
      m.set_twin(b, ta);
      m.set_twin(ta, b);
      break;
    }
    case 4: {
      const HalfedgeId na = m.next(a);
      m.set_next(a, m.next(b));
      m.set_next(b, na);
      break;
    }
    case 5: {
      const VertexId va = m.vertex(a);
      m.set_vertex(a, m.vertex(b));
      m.set_vertex(b, va);
      break;
    }
    case 6: {
      const FaceId fa = m.face(a);
      m.set_face(a, m.face(b));
      m.set_face(b, fa);
      break;
    }
    case 7: m.set_halfedge(m.face(a), m.next(a)); break;             // valid: another halfedge of the same cycle
    default: m.set_halfedge(m.vertex(a), m.next(m.twin(a))); break;  // valid: another halfedge of the same fan
  }
}

TEST(PatchCheck, AgreesWithTheWholeMeshCheckOnRandomEdits) {
  size_t kept_clean = 0, broken = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    HalfedgeMesh mesh = fixture(seed);
    std::mt19937 random(seed);
    for (int step = 0; step < 12; ++step) {
      ASSERT_TRUE(mesh_is_clean(mesh));
      const HalfedgeMesh before = mesh;
      const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) {
        switch (random() % 3) {
          case 0: testing::break_randomly(m, random); break;
          case 1: rewire_randomly(m, random); break;
          default: testing::random_edit_or_write(m, random); break;
        }
      });
      const bool clean = mesh_is_clean(mesh);
      ASSERT_EQ(edit_keeps_clean(mesh, patch), clean) << "step " << step;
      if (!clean) {
        ++broken;
        mesh = before;
        continue;
      }
      ++kept_clean;
      EXPECT_TRUE(validate_without_shortcut(mesh).ok());
      // Undo's direction: from the clean state after back to the clean state before.
      EXPECT_TRUE(edit_keeps_clean(before, patch.reversed()));
    }
  }
  // Both answers are exercised often.
  EXPECT_GT(kept_clean, 1000u);
  EXPECT_GT(broken, 1000u);
}

// Every flip, split and collapse the core allows, on every edge of meshes with boundaries, quads and dead slots,
// is seen as clean by the local check (so the window never falls back to a whole-mesh pass after them).
TEST(PatchCheck, AcceptsEveryOperationOnEveryEdge) {
  for (uint32_t seed = 0; seed < 4; ++seed) {
    const HalfedgeMesh start = fixture(seed);
    for (uint32_t i = 0; i < start.edge_capacity(); ++i) {
      const EdgeId e(i);
      if (!start.alive(e)) continue;
      for (int op = 0; op < 3; ++op) {
        SCOPED_TRACE("seed " + std::to_string(seed) + " e" + std::to_string(i) + " op " + std::to_string(op));
        HalfedgeMesh mesh = start;
        bool done = false;
        const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) {
          done = op == 0 ? flip(m, e).ok() : op == 1 ? split(m, e).ok() : collapse(m, e).ok();
        });
        if (!done) continue;
        ASSERT_TRUE(validate_without_shortcut(mesh).ok());
        EXPECT_TRUE(edit_keeps_clean(mesh, patch));
        EXPECT_TRUE(edit_keeps_clean(start, patch.reversed()));
      }
    }
  }
}

// Breaks whose slots the edit never touched: the neighbours that read them are re-checked.
TEST(PatchCheck, RefusesAVertexOrFaceDeletedUnderItsHalfedges) {
  const HalfedgeMesh start = build_halfedge_mesh(make_torus(6, 5));
  HalfedgeMesh mesh = start;
  MeshPatch patch = patch_of(mesh, [](HalfedgeMesh& m) { m.delete_element(VertexId(7)); });
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));

  mesh = start;
  patch = patch_of(mesh, [](HalfedgeMesh& m) { m.delete_element(FaceId::face(3)); });
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));
}

// A face that takes over another, non-adjacent face's halfedges: every rule passes, but the face now has two
// cycles and the one not reached from its halfedge is counted by no face (only the cycle sum can tell).
TEST(PatchCheck, RefusesAFaceWithTwoCycles) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(6, 5));
  const FaceId f = FaceId::face(0), g = FaceId::face(20);
  const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) {
    std::vector<HalfedgeId> cycle;
    m.for_each_face_halfedge(g, [&](HalfedgeId h) { cycle.push_back(h); });
    for (const HalfedgeId h : cycle) m.set_face(h, f);
    m.delete_element(g);
  });
  EXPECT_FALSE(mesh_is_clean(mesh));
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));
}

// A vertex that takes over another, non-adjacent vertex's halfedges (an hourglass): every rule passes, but the fan
// from the vertex's halfedge misses the other half, which no fan counts (only the fan sum can tell).
TEST(PatchCheck, RefusesAVertexWithTwoFans) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(6, 5));
  const VertexId kept(0), merged(15);
  const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) {
    std::vector<HalfedgeId> fan;
    m.for_each_outgoing(merged, [&](HalfedgeId h) { fan.push_back(h); });
    for (const HalfedgeId h : fan) {
      ASSERT_NE(m.vertex(m.twin(h)), kept);  // not neighbours
      m.set_vertex(h, kept);
    }
    m.delete_element(merged);
  });
  EXPECT_FALSE(mesh_is_clean(mesh));
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));
}

// A twin pair moved onto a new edge, leaving the old edge alive and still pointing at it: the pair and the new edge
// are well formed; only the old edge's rule sees that its halfedge lies on another edge.
TEST(PatchCheck, RefusesAnEdgeLeftPointingAtAPairThatMoved) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(6, 5));
  const EdgeId old_edge(4);
  const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) {
    const HalfedgeId h = m.halfedge(old_edge);
    const EdgeId moved = m.new_edge();
    m.set_edge(h, moved);
    m.set_edge(m.twin(h), moved);
    m.set_halfedge(moved, h);
  });
  EXPECT_FALSE(mesh_is_clean(mesh));
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));
}

// A new halfedge paired with a new twin, both well formed on their own but in no face cycle: every rule of the slots
// the edit wrote may pass, and only the coverage sums can see the two halfedges no cycle holds.
TEST(PatchCheck, RefusesHalfedgesNoCycleHolds) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(6, 5));
  const MeshPatch patch = patch_of(mesh, [](HalfedgeMesh& m) {
    const HalfedgeId a = m.new_halfedge(), b = m.new_halfedge();
    const EdgeId e = m.new_edge();
    const HalfedgeId n0 = m.next(m.halfedge(FaceId::face(0))), n9 = m.next(m.halfedge(FaceId::face(20)));
    ASSERT_NE(m.vertex(n0), m.vertex(n9));
    m.set_neighbors(a, n0, b, m.vertex(n9), e, FaceId::face(0));  // a's next is in a's face and leaves b's vertex
    m.set_neighbors(b, n9, a, m.vertex(n0), e, FaceId::face(20));
    m.set_halfedge(e, a);
  });
  EXPECT_FALSE(mesh_is_clean(mesh));
  EXPECT_FALSE(edit_keeps_clean(mesh, patch));
}

// The patch must end in the mesh given: the state before, or the same edit made elsewhere, is refused.
TEST(PatchCheck, RefusesAPatchThatDoesNotEndInTheMesh) {
  const HalfedgeMesh start = build_halfedge_mesh(make_torus(6, 5));
  HalfedgeMesh flipped = start;
  const MeshPatch flip_patch = patch_of(flipped, [](HalfedgeMesh& m) { ASSERT_TRUE(flip(m, EdgeId(4)).ok()); });
  ASSERT_TRUE(edit_keeps_clean(flipped, flip_patch));
  EXPECT_FALSE(edit_keeps_clean(start, flip_patch));  // listed slots hold their `before` values

  HalfedgeMesh split_mesh = start;
  const MeshPatch split_patch = patch_of(split_mesh, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(4)).ok()); });
  EXPECT_FALSE(edit_keeps_clean(start, split_patch));    // shape differs
  EXPECT_FALSE(edit_keeps_clean(flipped, split_patch));  // shape differs

  MeshPatch unsorted = flip_patch;
  std::swap(unsorted.slots.front(), unsorted.slots.back());
  EXPECT_FALSE(edit_keeps_clean(flipped, unsorted));

  MeshPatch missing_new_slot = split_patch;  // drops an appended slot: it can no longer be read before
  missing_new_slot.slots.pop_back();
  EXPECT_FALSE(edit_keeps_clean(split_mesh, missing_new_slot));
}

}  // namespace
}  // namespace meshedit
