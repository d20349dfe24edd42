// The builder's fast path: the checked builder's exact mesh (ids in the order mesh_build.h specifies) for clean
// input, in a few sequential passes and one table of outgoing halfedges, with no error bookkeeping.
//
// How it differs from the checked builder (mesh_build.cpp), which stays the reference and the only place that
// explains a refusal: the outgoing halfedges of each vertex are stored as (head << 32 | halfedge) keys (no head
// lookups while searching), twins are found by scanning the head vertex's few keys, each pair once, fans are walked
// on the twin table (a triangle's next corner is arithmetic), and the pointers are written straight into the mesh's
// arrays. Anything unusual (a face with fewer than 3 or more
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

namespace meshedit::build_detail {
namespace {

constexpr uint32_t kNone = kInvalidIndex;
constexpr uint32_t kMaxFastCorners = 16;  // bigger polygons take the checked path (quadratic corner check here)

uint32_t key_head(uint64_t key) { return uint32_t(key >> 32); }
uint32_t key_halfedge(uint64_t key) { return uint32_t(key); }

// Whether every face is a triangle: face f's corners are 3f, 3f + 1, 3f + 2.
bool all_triangles(const PolygonMesh& in) {
  if (in.indices.size() != 3 * in.num_faces()) return false;
  uint32_t differ = 0;
  for (size_t f = 0; f <= in.num_faces(); ++f) differ |= in.face_offsets[f] ^ uint32_t(3 * f);
  return differ == 0;
}

// Every face has 3..kMaxFastCorners distinct corners, all in range. `triangles`: all_triangles(in).
bool faces_are_clean(const PolygonMesh& in, bool triangles) {
  const uint32_t vertices = uint32_t(in.num_vertices());
  const uint32_t* idx = in.indices.data();
  if (triangles) {
    bool clean = true;
    for (size_t c = 0; c < in.indices.size(); c += 3) {
      const uint32_t a = idx[c], b = idx[c + 1], d = idx[c + 2];
      clean &= a < vertices && b < vertices && d < vertices && a != b && b != d && a != d;
    }
    return clean;
  }
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

// Outgoing halfedges by tail vertex: keys[start[v] .. start[v + 1]) = (head << 32 | h). A vertex's keys are in
// corner order, except that more than kSortedAbove of them are sorted (so by head) for binary search; a few keys
// are scanned faster than sorted.
struct Outgoing {
  static constexpr uint32_t kSortedAbove = 16;
  MeshArray<uint32_t> start;
  MeshArray<uint64_t> keys;

  uint32_t count(uint32_t v) const { return start[v + 1] - start[v]; }

  // v's key with head u, or null.
  const uint64_t* find(uint32_t v, uint32_t u) const {
    const uint64_t* first = keys.data() + start[v];
    const uint64_t* last = keys.data() + start[v + 1];
    if (count(v) > kSortedAbove) {
      first = std::lower_bound(first, last, uint64_t(u) << 32);
      return first != last && key_head(*first) == u ? first : nullptr;
    }
    for (; first != last; ++first) {
      if (key_head(*first) == u) return first;
    }
    return nullptr;
  }

  // Whether no two of v's keys have the same head (two halfedges v -> u are a doubled edge).
  bool heads_distinct(uint32_t v) const {
    const uint64_t* first = keys.data() + start[v];
    const uint64_t* last = keys.data() + start[v + 1];
    if (count(v) > kSortedAbove) {
      return std::adjacent_find(first, last, [](uint64_t a, uint64_t b) { return key_head(a) == key_head(b); }) == last;
    }
    for (const uint64_t* i = first; i != last; ++i) {
      for (const uint64_t* j = i + 1; j != last; ++j) {
        if (key_head(*i) == key_head(*j)) return false;
      }
    }
    return true;
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
    if (out.count(uint32_t(v)) > Outgoing::kSortedAbove) {
      std::sort(out.keys.data() + out.start[v], out.keys.data() + out.start[v + 1]);
    }
  }
  return out;
}

// The corner after h around its face, when every face is a triangle (corners 3f, 3f + 1, 3f + 2).
uint32_t triangle_next(uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }

// Interior twins; false on a doubled edge (two halfedges u -> v, seen in u's keys), and, when every face is a
// triangle, on two triangles glued along an edge with the same third corner (one face repeated). Each pair is
// looked up once, from its lower vertex.
bool match_twins(const PolygonMesh& in, const Outgoing& out, bool triangles, MeshArray<uint32_t>& twin) {
  twin.assign(in.indices.size(), kNone);
  const uint32_t* idx = in.indices.data();
  for (uint32_t u = 0; u < in.num_vertices(); ++u) {
    if (!out.heads_distinct(u)) return false;
    const uint32_t end = out.start[u + 1];
    for (uint32_t i = out.start[u]; i < end; ++i) {
      const uint32_t v = key_head(out.keys[i]);
      if (v < u) continue;
      const uint64_t* reverse = out.find(v, u);
      if (!reverse) continue;
      const uint32_t h = key_halfedge(out.keys[i]), t = key_halfedge(*reverse);
      if (triangles && idx[triangle_next(triangle_next(h))] == idx[triangle_next(triangle_next(t))]) return false;
      twin[h] = t;
      twin[t] = h;
    }
  }
  return true;
}

// Whether every vertex's fan reaches all its outgoing halfedges (the interior ones, and the open one on a hole); one
// that does not joins several surfaces (a bow-tie). Walks h -> h.twin.next on the twin table, with next_of(h) the
// next corner around h's face; the open halfedge leaving v sits between an open interior halfedge and
// next_of(open_incoming[v]). Every walk ends: next is a permutation and twin an involution, so the walk returns to
// its start through that vertex's outgoing halfedges only (the count below is a guard, not the proof).
template <class NextOf>
bool every_fan_whole(const Outgoing& out, std::span<const uint32_t> twin, std::span<const uint32_t> open_incoming,
                     NextOf next_of) {
  for (uint32_t v = 0; v + 1 < out.start.size(); ++v) {
    if (out.count(v) == 0) continue;  // unused: no fan
    const uint32_t outgoing = out.count(v) + (open_incoming[v] != kNone ? 1 : 0);
    const uint32_t first = key_halfedge(out.keys[out.start[v]]);
    uint32_t h = first, walked = 0;
    do {
      const uint32_t t = twin[h];
      walked += t == kNone ? 2 : 1;  // an open h, then the open halfedge after it
      if (walked > outgoing || (t == kNone && open_incoming[v] == kNone)) return false;
      h = next_of(t == kNone ? open_incoming[v] : t);
    } while (h != first);
    if (walked != outgoing) return false;
  }
  return true;
}

// Sorted corners of face f, for the (rare) repeated-polygon check.
std::vector<uint32_t> sorted_corners(const PolygonMesh& in, uint32_t f) {
  std::vector<uint32_t> s(in.indices.begin() + in.face_offsets[f], in.indices.begin() + in.face_offsets[f + 1]);
  std::sort(s.begin(), s.end());
  return s;
}

}  // namespace

MeshArray<uint32_t> number_edges(std::span<const uint32_t> twin) {
  MeshArray<uint32_t> edge_of;
  edge_of.resize_for_overwrite(twin.size());  // every entry written below
  uint32_t next_edge = 0;
  for (uint32_t h = 0; h < twin.size(); ++h) {
    const uint32_t t = twin[h];  // kNone (open) is above every halfedge
    edge_of[h] = t > h ? next_edge++ : edge_of[t];
  }
  return edge_of;
}

void write_face_halfedges(const PolygonMesh& in, std::span<const uint32_t> twin, size_t num_halfedges,
                          HalfedgeMesh& mesh) {
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  m.h.resize_for_overwrite(num_halfedges);  // interior records written here, boundary ones by finish_build
  m.h_alive.assign(num_halfedges, true);
  HalfedgeRecord* records = m.h.data();
  m.f_halfedge.resize_for_overwrite(in.num_faces());  // every face's written below
  m.f_alive.assign(in.num_faces(), true);
  uint32_t next_edge = 0;
  for (uint32_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
    m.f_halfedge[f] = HalfedgeId(begin);
    for (uint32_t h = begin; h < end; ++h) {
      // number_edges' numbering: halfedges are written in id order, so a lower twin's record already has its edge.
      const uint32_t t = twin[h];  // kNone (open) is above every halfedge
      const uint32_t edge = t > h ? next_edge++ : records[t].edge.index;
      records[h] = HalfedgeRecord{HalfedgeId(h + 1 < end ? h + 1 : begin), HalfedgeId(t), VertexId(in.indices[h]),
                                  EdgeId(edge), FaceId::face(f)};
    }
  }
}

bool build_fast(const PolygonMesh& in, HalfedgeMesh& mesh, size_t& unused_vertices) {
  const bool triangles = all_triangles(in);
  if (!faces_are_clean(in, triangles)) return false;
  const uint32_t num_interior = uint32_t(in.indices.size());
  const uint32_t num_vertices = uint32_t(in.num_vertices());
  const uint32_t* idx = in.indices.data();

  MeshArray<uint32_t> twin;
  const Outgoing out = outgoing_table(in);
  if (!match_twins(in, out, triangles, twin)) return false;

  // Boundary: at most one open halfedge may arrive at each vertex.
  MeshArray<uint32_t> open_incoming(num_vertices, kNone);
  uint32_t num_boundary = 0;
  const auto open_arrives = [&](uint32_t h, uint32_t head) {
    if (open_incoming[head] != kNone) return false;
    open_incoming[head] = h;
    ++num_boundary;
    return true;
  };
  if (triangles) {
    for (uint32_t h = 0; h < num_interior; ++h) {
      if (twin[h] == kNone && !open_arrives(h, idx[triangle_next(h)])) return false;
    }
  } else {
    for (size_t f = 0; f < in.num_faces(); ++f) {
      const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
      for (uint32_t h = begin; h < end; ++h) {
        if (twin[h] == kNone && !open_arrives(h, idx[h + 1 < end ? h + 1 : begin])) return false;
      }
    }
  }
  const uint32_t num_halfedges = num_interior + num_boundary;
  if (num_halfedges >= kNone / 2) return false;

  write_face_halfedges(in, twin, num_halfedges, mesh);
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  const HalfedgeRecord* records = m.h.data();

  // Two polygons glued along an edge with the same corners are one face repeated (triangles: match_twins).
  for (uint32_t h = 0; h < num_interior && !triangles; ++h) {
    const uint32_t t = twin[h];
    if (t == kNone || t < h) continue;
    const uint32_t f = records[h].face.slot(), g = records[t].face.slot();
    const uint32_t size_f = in.face_offsets[f + 1] - in.face_offsets[f];
    if (size_f != in.face_offsets[g + 1] - in.face_offsets[g]) continue;
    if (sorted_corners(in, f) == sorted_corners(in, g)) return false;
  }
  const bool fans_whole =
      triangles ? every_fan_whole(out, twin, open_incoming, triangle_next)
                : every_fan_whole(out, twin, open_incoming, [records](uint32_t h) { return records[h].next.index; });
  if (!fans_whole) return false;

  const size_t unused = finish_build(in, twin, open_incoming, mesh);
  unused_vertices = unused;
  // Vouched only as valid as validate() would find it: triangles, every vertex used, every position finite.
  const bool finite_positions =
      std::all_of(in.positions.begin(), in.positions.end(), [](const glm::dvec3& p) { return finite(p); });
  if (triangles && unused == 0 && finite_positions) {
    MeshStorage::vouch_valid_triangles(mesh);
  }
  return true;
}

}  // namespace meshedit::build_detail
