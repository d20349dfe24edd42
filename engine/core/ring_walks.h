// ring_walks: walks the one-rings of a range of vertices several at a time, for whole-mesh passes that would
// otherwise spend their time waiting on memory (Loop's vertex pass). One walk is a chain of dependent loads:
// h -> h.twin -> the twin's vertex and position, and the twin's next -> the next h. On a mesh of millions of
// elements each link is likely a cache miss, and a plain walk has one in flight at a time. walk_rings keeps
// kLanes walks going side by side: each round advances every walk by one link whose memory it prefetched the round
// before, so up to kLanes misses overlap.
//
// Invariants: each vertex's neighbours reach the visitor in the walk order of loop_rules.h (from v.halfedge, h ->
// h.twin.next), so sums made from them are bit-identical to a plain walk's; a vertex's begin() comes before its
// neighbours and its end() after the last of them, on the same lane; vertices start in increasing index order;
// dead vertices are skipped. walk_rings only reads the mesh. Like any ring walk it assumes valid rings (every walk
// comes back to its start): callers have checked the mesh.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/memory_hints.h"
#include "core/mesh_storage.h"

namespace meshedit::ring_walks {

inline constexpr unsigned kLanes = 16;

// Visitor: begin(lane, v), neighbour(lane, q, rim) for each neighbour vertex q of v in walk order (rim: the edge to
// q lies on a boundary; q's position was prefetched), end(lane, v, start) with start = v.halfedge.
template <class Visitor>
void walk_rings(const MeshStorage::View& m, size_t begin, size_t end, Visitor& visitor) {
  enum class Stage : uint8_t { Idle, AtHalfedge, AtTwin, Finishing };
  struct Lane {
    Stage stage = Stage::Idle;
    bool has_pending = false, pending_rim = false, h_on_boundary = false;
    uint32_t v = 0, start = 0, h = 0, t = 0, pending = 0;
  };
  Lane lanes[kLanes];
  size_t next_vertex = begin;
  unsigned active = 0;

  // Puts the next live vertex (if any) on `lane`; its first halfedge is prefetched.
  const auto take_vertex = [&](unsigned index, Lane& lane) {
    while (next_vertex < end && !(*m.vertex_alive)[next_vertex]) ++next_vertex;
    if (next_vertex == end) {
      lane.stage = Stage::Idle;
      return;
    }
    lane.v = uint32_t(next_vertex++);
    lane.start = lane.h = m.vertex_halfedge[lane.v].index;
    memory_hints::prefetch_record(&m.h[lane.h]);
    lane.has_pending = false;
    lane.stage = Stage::AtHalfedge;
    visitor.begin(index, lane.v);
  };
  const auto deliver_pending = [&](unsigned index, Lane& lane) {
    if (lane.has_pending) visitor.neighbour(index, lane.pending, lane.pending_rim);
    lane.has_pending = false;
  };

  for (unsigned index = 0; index < kLanes; ++index) {
    take_vertex(index, lanes[index]);
    if (lanes[index].stage != Stage::Idle) ++active;
  }
  while (active > 0) {
    for (unsigned index = 0; index < kLanes; ++index) {
      Lane& lane = lanes[index];
      switch (lane.stage) {
        case Stage::Idle: break;
        case Stage::AtHalfedge: {  // h's record was prefetched: find its twin
          deliver_pending(index, lane);
          const HalfedgeRecord& r = m.h[lane.h];
          lane.t = r.twin.index;
          lane.h_on_boundary = r.face.is_boundary();
          memory_hints::prefetch_record(&m.h[lane.t]);
          lane.stage = Stage::AtTwin;
          break;
        }
        case Stage::AtTwin: {  // the twin's record was prefetched: its vertex is the next neighbour
          const HalfedgeRecord& r = m.h[lane.t];
          lane.pending = r.vertex.index;
          lane.pending_rim = lane.h_on_boundary || r.face.is_boundary();
          lane.has_pending = true;
          memory_hints::prefetch(&m.position[lane.pending]);
          lane.h = r.next.index;
          if (lane.h == lane.start) {
            lane.stage = Stage::Finishing;
          } else {
            memory_hints::prefetch_record(&m.h[lane.h]);
            lane.stage = Stage::AtHalfedge;
          }
          break;
        }
        case Stage::Finishing:
          deliver_pending(index, lane);
          visitor.end(index, lane.v, lane.start);
          take_vertex(index, lane);
          if (lane.stage == Stage::Idle) --active;
          break;
      }
    }
  }
}

}  // namespace meshedit::ring_walks
