// The builder's fast path: the checked builder's exact mesh (ids in the order mesh_build.h specifies) for clean
// input, in a few sequential passes and one table of outgoing halfedges, with no error bookkeeping.
//
// How it differs from the checked builder (mesh_build.cpp), which stays the reference and the only place that
// explains a refusal: the outgoing halfedges of each vertex are stored as (head << 32 | halfedge) keys sorted in
// place (no head lookups while sorting or searching), twins are found by scanning the head vertex's few keys, and
// the pointers are written straight into the mesh's arrays. Anything unusual (a face with fewer than 3 or more
// than kMaxFastCorners corners, a repeated corner, an index out of range, a doubled or inconsistent edge, a
// repeated face, a bow-tie) makes it return false at once, and build_halfedge_mesh reruns the checked builder.
// tests/core/mesh_build_fast_test.cpp holds the two to the same result.
#include "core/mesh_build_fast.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/finite.h"
#include "core/mesh_array.h"
#include "core/mesh_storage.h"
#include "core/ring_walks.h"

namespace meshedit::build_detail {
namespace {

constexpr uint32_t kNone = kInvalidIndex;
constexpr uint32_t kMaxFastCorners = 16;  // bigger polygons take the checked path (quadratic corner check here)

uint32_t key_head(uint64_t key) { return uint32_t(key >> 32); }
uint32_t key_halfedge(uint64_t key) { return uint32_t(key); }

// Every face has 3..kMaxFastCorners distinct corners, all in range.
bool faces_are_clean(const PolygonMesh& in) {
  const uint32_t vertices = uint32_t(in.num_vertices());
  const uint32_t* idx = in.indices.data();
  for (size_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1], n = end - begin;
    if (n < 3 || n > kMaxFastCorners) return false;
    for (uint32_t i = begin; i < end; ++i) {
      if (idx[i] >= vertices) return false;
      for (uint32_t j = begin; j < i; ++j) {
        if (idx[j] == idx[i]) return false;
      }
    }
  }
  return true;
}

// Outgoing halfedges by tail vertex: keys[start[v] .. start[v + 1]) = (head << 32 | h), sorted (so by head).
struct Outgoing {
  MeshArray<uint32_t> start;
  MeshArray<uint64_t> keys;

  uint32_t count(uint32_t v) const { return start[v + 1] - start[v]; }

  // The first key of v whose head is >= u (or the range's end).
  const uint64_t* lower(uint32_t v, uint32_t u) const {
    const uint64_t* first = keys.data() + start[v];
    const uint64_t* last = keys.data() + start[v + 1];
    if (last - first <= 16) {
      while (first != last && key_head(*first) < u) ++first;
      return first;
    }
    return std::lower_bound(first, last, uint64_t(u) << 32);
  }
};

Outgoing outgoing_table(const PolygonMesh& in) {
  const size_t vertices = in.num_vertices();
  const uint32_t* idx = in.indices.data();
  Outgoing out;
  out.start.assign(vertices + 1, 0);
  for (uint32_t v : in.indices) ++out.start[v + 1];
  for (size_t v = 0; v < vertices; ++v) out.start[v + 1] += out.start[v];
  out.keys.resize_for_overwrite(in.indices.size());  // every key written below
  MeshArray<uint32_t> cursor;
  cursor.assign(out.start.begin(), out.start.end() - 1);
  for (size_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
    for (uint32_t h = begin; h < end; ++h) {
      const uint32_t head = idx[h + 1 < end ? h + 1 : begin];
      out.keys[cursor[idx[h]]++] = (uint64_t(head) << 32) | h;
    }
  }
  for (size_t v = 0; v < vertices; ++v) {
    uint64_t* first = out.keys.data() + out.start[v];
    uint64_t* last = out.keys.data() + out.start[v + 1];
    if (last - first <= 16) {
      for (uint64_t* i = first + 1; i < last; ++i) {  // insertion sort: valences are small
        const uint64_t k = *i;
        uint64_t* j = i;
        for (; j > first && *(j - 1) > k; --j) *j = *(j - 1);
        *j = k;
      }
    } else {
      std::sort(first, last);
    }
  }
  return out;
}

// Interior twins; false on a doubled edge (two halfedges u -> v) or an edge with two halfedges v -> u.
bool match_twins(const PolygonMesh& in, const Outgoing& out, MeshArray<uint32_t>& twin) {
  twin.assign(in.indices.size(), kNone);
  for (uint32_t u = 0; u < in.num_vertices(); ++u) {
    const uint32_t end = out.start[u + 1];
    for (uint32_t i = out.start[u]; i < end; ++i) {
      const uint32_t v = key_head(out.keys[i]);
      if (i + 1 < end && key_head(out.keys[i + 1]) == v) return false;
      const uint64_t* reverse = out.lower(v, u);
      const uint64_t* last = out.keys.data() + out.start[v + 1];
      if (reverse == last || key_head(*reverse) != u) continue;
      if (reverse + 1 != last && key_head(reverse[1]) == u) return false;
      twin[key_halfedge(out.keys[i])] = key_halfedge(*reverse);
    }
  }
  return true;
}

// Sorted corners of face f, for the (rare) repeated-polygon check.
std::vector<uint32_t> sorted_corners(const PolygonMesh& in, uint32_t f) {
  std::vector<uint32_t> s(in.indices.begin() + in.face_offsets[f], in.indices.begin() + in.face_offsets[f + 1]);
  std::sort(s.begin(), s.end());
  return s;
}

// Counts each vertex's fan (its ring walk) against its outgoing halfedges, the interior ones and the open one.
class FanCount {
 public:
  FanCount(const Outgoing& out, std::span<const uint32_t> open_incoming) : out_(out), open_incoming_(open_incoming) {}

  void begin(unsigned lane, uint32_t) { walked_[lane] = 0; }
  void neighbour(unsigned lane, uint32_t, bool) { ++walked_[lane]; }
  void end(unsigned lane, uint32_t v, uint32_t) {
    const uint32_t outgoing = out_.count(v) + (open_incoming_[v] != kNone ? 1 : 0);
    whole_ = whole_ && walked_[lane] == outgoing;
  }
  bool whole() const { return whole_; }

 private:
  const Outgoing& out_;
  std::span<const uint32_t> open_incoming_;
  uint32_t walked_[ring_walks::kLanes] = {};
  bool whole_ = true;
};

// Whether every vertex's fan reaches all its outgoing halfedges; one that does not joins several surfaces (a
// bow-tie). Every walk ends: next is a permutation (face cycles and hole loops) and twin an involution, so the walk
// h -> h.twin.next from a vertex's halfedge returns to it through that vertex's outgoing halfedges only.
bool every_fan_whole(const Outgoing& out, std::span<const uint32_t> open_incoming, HalfedgeMesh& mesh) {
  FanCount count(out, open_incoming);
  ring_walks::walk_rings(MeshStorage::view(mesh), 0, mesh.vertex_capacity(), count);
  return count.whole();
}

}  // namespace

void write_face_halfedges(const PolygonMesh& in, std::span<const uint32_t> twin, size_t num_halfedges,
                          HalfedgeMesh& mesh) {
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  m.h.resize_for_overwrite(num_halfedges);  // interior records written here, boundary ones by finish_build
  m.h_alive.assign(num_halfedges, true);
  HalfedgeRecord* h_ = m.h.data();
  m.f_halfedge.resize_for_overwrite(in.num_faces());  // every face's written below
  m.f_alive.assign(in.num_faces(), true);
  for (uint32_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
    m.f_halfedge[f] = HalfedgeId(begin);
    for (uint32_t h = begin; h < end; ++h) {  // the edge stays unset (invalid) for finish_build to number
      h_[h] = HalfedgeRecord{HalfedgeId(h + 1 < end ? h + 1 : begin), HalfedgeId(twin[h]), VertexId(in.indices[h]),
                             EdgeId(), FaceId::face(f)};
    }
  }
}

bool build_fast(const PolygonMesh& in, HalfedgeMesh& mesh, size_t& unused_vertices) {
  if (!faces_are_clean(in)) return false;
  const uint32_t num_interior = uint32_t(in.indices.size());
  const uint32_t num_vertices = uint32_t(in.num_vertices());
  const uint32_t* idx = in.indices.data();

  MeshArray<uint32_t> twin;
  const Outgoing out = outgoing_table(in);
  if (!match_twins(in, out, twin)) return false;

  // Boundary: at most one open halfedge may arrive at each vertex.
  MeshArray<uint32_t> open_incoming(num_vertices, kNone);
  uint32_t num_boundary = 0;
  for (size_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
    for (uint32_t h = begin; h < end; ++h) {
      if (twin[h] != kNone) continue;
      const uint32_t head = idx[h + 1 < end ? h + 1 : begin];
      if (open_incoming[head] != kNone) return false;
      open_incoming[head] = h;
      ++num_boundary;
    }
  }
  const uint32_t num_halfedges = num_interior + num_boundary;
  if (num_halfedges >= kNone / 2) return false;

  write_face_halfedges(in, twin, num_halfedges, mesh);
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  const HalfedgeRecord* h_ = m.h.data();

  // Two faces glued along an edge with the same corners are one face repeated.
  for (uint32_t h = 0; h < num_interior; ++h) {
    const uint32_t t = twin[h];
    if (t == kNone || t < h) continue;
    const uint32_t f = h_[h].face.slot(), g = h_[t].face.slot();
    const uint32_t size_f = in.face_offsets[f + 1] - in.face_offsets[f];
    if (size_f != in.face_offsets[g + 1] - in.face_offsets[g]) continue;
    const bool same = size_f == 3
                          ? h_[h_[h_[h].next.index].next.index].vertex == h_[h_[h_[t].next.index].next.index].vertex
                          : sorted_corners(in, f) == sorted_corners(in, g);
    if (same) return false;
  }

  const size_t unused = finish_build(in, twin, open_incoming, mesh);

  if (!every_fan_whole(out, open_incoming, mesh)) return false;
  unused_vertices = unused;
  // Vouched only as valid as validate() would find it: triangles, every vertex used, every position finite.
  const bool finite_positions =
      std::all_of(in.positions.begin(), in.positions.end(), [](const glm::dvec3& p) { return finite(p); });
  if (in.indices.size() == 3 * in.num_faces() && unused == 0 && finite_positions) {
    MeshStorage::vouch_valid_triangles(mesh);
  }
  return true;
}

}  // namespace meshedit::build_detail
