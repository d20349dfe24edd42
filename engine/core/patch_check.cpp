// edit_keeps_clean (patch_check.h): re-checks only the elements whose quick-check rule (clean_rules.h) an edit can
// have changed, and keeps quick_check.cpp's two coverage sums by taking off the old lengths and adding the new.
//
// Why these elements are enough. Call the mesh before the edit B (clean) and after it A; a slot the patch does not
// list has the same values in both. A rule reads only the fields listed beside it in clean_rules.h, so the rule of
// an unlisted element can change only through an element it reads that is listed:
// - halfedge h reads twin(h), next(h), edge(h), and whether vertex(h) and face(h) are live. As h's fields are B's,
//   a listed x is read by h only when h = twin_B(x) or next_B(h) = x (h = prev_B(x)); a listed edge e only when h is
//   one of B's pair on e; a vertex or face that died only when h leaves it (B's fan) or lies in it (B's cycle).
// - edge e reads halfedge(e): listed x matters to e = edge_B(x).
// - face f's cycle walks from halfedge(f) through next: with no listed halfedge on B's cycle, A's walk is B's, step
//   by step. So only faces listed or holding a listed halfedge in B (face_B(x)) can change.
// - vertex v's fan reads each h leaving v and twin(h): listed x matters to vertex_B(x) and vertex_B(twin_B(x)).
// Every other rule gives in A what it gave in B (true), and every other cycle and fan has its B length, so A's sums
// are B's (the live halfedge count before) minus the old lengths of the re-walked ones plus their new lengths.
// Hence the answer equals mesh_is_clean(A) whenever B was clean. The state before is read through the patch.
// (Some suspects, such as prev_B(x) or the fan of a vertex that died, would also be caught by the sums; they are kept
// so that each rule's argument stands on its own, and they cost a few reads.)
#include "core/patch_check.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/clean_rules.h"
#include "core/state_before.h"

namespace meshedit {
namespace {

// True when the patch ends in `after` exactly where it says anything (shape, listed slots' `after` values), is
// sorted with each slot once, and lists every slot that exists in only one of the two states.
bool patch_ends_in(const HalfedgeMesh& after, const MeshPatch& patch) {
  const MeshShape shape = shape_of(after);
  size_t listed_in_one_state[kElementKindCount] = {};
  for (size_t i = 0; i < patch.slots.size(); ++i) {
    const SlotChange& change = patch.slots[i];
    if (i > 0 && !(slot_key(patch.slots[i - 1]) < slot_key(change))) return false;
    const int k = int(change.kind);
    const uint32_t a = shape.capacity[k], b = patch.shape_before.capacity[k];
    if (change.slot < a && !same_state(read_slot(after, change.kind, change.slot), change.after)) return false;
    if (change.slot >= std::min(a, b) && change.slot < std::max(a, b)) ++listed_in_one_state[k];
  }
  for (int k = 0; k < kElementKindCount; ++k) {
    const uint32_t a = shape.capacity[k], b = patch.shape_before.capacity[k];
    if (a != patch.shape_after.capacity[k] || shape.live[k] != patch.shape_after.live[k]) return false;
    if (listed_in_one_state[k] != std::max(a, b) - std::min(a, b)) return false;
  }
  return true;
}

// The mesh before the edit (core/state_before.h), with the walks the suspects need. Walks give 0 (and the check then
// says false) if they do not close within the live halfedge count before, which a clean B never does.
class CheckedBefore : public StateBefore {
 public:
  CheckedBefore(const HalfedgeMesh& after, const MeshPatch& patch)
      : StateBefore(after, patch), live_(num_halfedges()) {}

  // Calls visit(h) for each halfedge leaving live vertex v (its fan from v's halfedge); returns how many, 0 if the
  // walk meets a dead halfedge or does not close.
  template <class Visit>
  size_t fan(VertexId v, Visit&& visit) const {
    return walk(
        halfedge(v),
        [&](HalfedgeId h) {
          const HalfedgeId twin = record(h).twin;
          return alive(twin) ? record(twin).next : HalfedgeId();
        },
        visit);
  }
  // The same for the halfedges of live face or boundary loop f (its next-cycle).
  template <class Visit>
  size_t cycle(FaceId f, Visit&& visit) const {
    return walk(
        halfedge(f), [&](HalfedgeId h) { return record(h).next; }, visit);
  }
  // The halfedge whose next is live halfedge x: the twin of the one before x in x's vertex fan. Invalid if none.
  HalfedgeId prev(HalfedgeId x) const {
    HalfedgeId before_x;
    const VertexId v = record(x).vertex;
    if (!alive(v)) return before_x;
    fan(v, [&](HalfedgeId h) {
      const HalfedgeId into = record(h).twin;
      if (alive(into) && record(into).next == x) before_x = into;
    });
    return before_x;
  }

 private:
  template <class Step, class Visit>
  size_t walk(HalfedgeId first, Step&& step, Visit&& visit) const {
    size_t length = 0;
    HalfedgeId h = first;
    do {
      if (!alive(h) || ++length > live_) return 0;
      visit(h);
      h = step(h);
    } while (h != first);
    return length;
  }

  size_t live_;
};

// The elements whose rules the edit may have changed (the header comment's list), each once.
struct Suspects {
  std::vector<HalfedgeId> halfedges;
  std::vector<EdgeId> edges;
  std::vector<FaceId> faces;  // faces and boundary loops
  std::vector<VertexId> vertices;
  bool walks_closed = true;  // false when a walk in the state before failed (it was not clean after all)
};

Suspects find_suspects(const HalfedgeMesh& after, const MeshPatch& patch, const CheckedBefore& before) {
  Suspects s;
  const auto note_walk = [&](size_t length) { s.walks_closed = s.walks_closed && length != 0; };
  const auto add_halfedge = [&](HalfedgeId h) { s.halfedges.push_back(h); };
  for (const SlotChange& change : patch.slots) {
    const ElementRef element(change.kind, change.slot);
    const bool was_alive = before.alive(element), died = was_alive && !after.alive(element);
    switch (change.kind) {
      case ElementKind::Vertex:
        s.vertices.push_back(VertexId(change.slot));
        if (died) note_walk(before.fan(VertexId(change.slot), add_halfedge));
        break;
      case ElementKind::Halfedge: {
        const HalfedgeId x(change.slot);
        s.halfedges.push_back(x);
        if (!was_alive) break;
        const HalfedgeRecord r = before.record(x);
        const HalfedgeId prev = before.prev(x);
        if (!before.alive(r.twin) || !prev.valid()) {
          s.walks_closed = false;
          break;
        }
        s.halfedges.insert(s.halfedges.end(), {r.twin, prev});
        s.edges.push_back(r.edge);
        s.faces.push_back(r.face);
        s.vertices.insert(s.vertices.end(), {r.vertex, before.record(r.twin).vertex});
        break;
      }
      case ElementKind::Edge: {
        s.edges.push_back(EdgeId(change.slot));
        if (!was_alive) break;
        const HalfedgeId h = before.halfedge(element);
        if (!before.alive(h)) {
          s.walks_closed = false;
          break;
        }
        s.halfedges.insert(s.halfedges.end(), {h, before.record(h).twin});
        break;
      }
      case ElementKind::Face:
      case ElementKind::Boundary:
        s.faces.push_back(element.face_id());
        if (died) note_walk(before.cycle(element.face_id(), add_halfedge));
        break;
    }
  }
  const auto unique = [](auto& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  };
  unique(s.halfedges);
  unique(s.edges);
  unique(s.faces);
  unique(s.vertices);
  return s;
}

// Takes the lengths of the walks from `ids` in the state before off `total` and adds those after (elements live in
// that state only); false when a walk fails its rule.
template <class Id, class OldLength, class NewLength>
bool swap_lengths(int64_t& total, const std::vector<Id>& ids, const CheckedBefore& before, const HalfedgeMesh& after,
                  OldLength&& old_length, NewLength&& new_length) {
  for (const Id id : ids) {
    if (before.alive(id)) {
      const size_t length = old_length(id);
      if (length == 0) return false;
      total -= int64_t(length);
    }
    if (after.alive(id)) {
      const size_t length = new_length(id);
      if (length == 0) return false;
      total += int64_t(length);
    }
  }
  return true;
}

}  // namespace

bool edit_keeps_clean(const HalfedgeMesh& after, const MeshPatch& patch) {
  if (!patch_ends_in(after, patch)) return false;
  const CheckedBefore before(after, patch);
  const Suspects s = find_suspects(after, patch, before);
  if (!s.walks_closed) return false;

  const size_t live = after.num_halfedges();
  const int64_t live_before = int64_t(patch.shape_before.live[int(ElementKind::Halfedge)]);
  for (const HalfedgeId h : s.halfedges) {
    if (after.alive(h) && !clean_rules::halfedge_ok(after, h)) return false;
  }
  for (const EdgeId e : s.edges) {
    if (after.alive(e) && !clean_rules::edge_ok(after, e)) return false;
  }

  // The sums: B's cycles and fans held live_before halfedges each way; swap the re-walked ones' lengths.
  const auto unused = [](HalfedgeId) {};
  int64_t in_cycles = live_before, in_fans = live_before;
  return swap_lengths(
             in_cycles, s.faces, before, after, [&](FaceId f) { return before.cycle(f, unused); },
             [&](FaceId f) { return clean_rules::cycle_length(after, f, live, false); }) &&
         in_cycles == int64_t(live) &&
         swap_lengths(
             in_fans, s.vertices, before, after, [&](VertexId v) { return before.fan(v, unused); },
             [&](VertexId v) { return clean_rules::fan_length(after, v, live); }) &&
         in_fans == int64_t(live);
}

}  // namespace meshedit
