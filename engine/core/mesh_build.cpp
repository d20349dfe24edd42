// Half-edge construction from indexed polygons (ids and refusals are specified in mesh_build.h).
// Clean input takes the fast path (mesh_build_fast.cpp), which builds the same mesh; everything else, and every
// refusal, goes through the checked build below.
//
// Twins are matched through the halfedges grouped by tail vertex and sorted by head vertex (a CSR
// table), so the build is O(H log d) with no hash map and no quadratic case, even for a vertex of huge
// valence in a hostile file.
#include "core/mesh_build.h"

#include <algorithm>
#include <sstream>

#include "core/mesh_build_fast.h"
#include "core/mesh_error.h"
#include "core/mesh_storage.h"

namespace meshedit {
namespace {

constexpr uint32_t kNone = kInvalidIndex;

std::string face_list(const std::vector<uint32_t>& faces) {
  std::ostringstream out;
  for (size_t i = 0; i < faces.size(); ++i) {
    if (i > 0) out << (i + 1 == faces.size() ? " and " : ", ");
    out << faces[i];
  }
  return out.str();
}

// Everything the builder derives before it touches the mesh, indexed by input halfedge.
struct Corners {
  const PolygonMesh& in;
  std::vector<uint32_t> face_of;    // input face of each halfedge
  std::vector<uint32_t> next;       // next halfedge in the same face
  std::vector<uint32_t> out_start;  // CSR: halfedges leaving vertex v are out[out_start[v] .. out_start[v+1])
  std::vector<uint32_t> out;        // ... sorted by head vertex

  uint32_t tail(uint32_t h) const { return in.indices[h]; }
  uint32_t head(uint32_t h) const { return in.indices[next[h]]; }

  // The halfedges u -> v, as a range of `out`.
  std::pair<const uint32_t*, const uint32_t*> find(uint32_t u, uint32_t v) const {
    const uint32_t* first = out.data() + out_start[u];
    const uint32_t* last = out.data() + out_start[u + 1];
    const auto* lo = std::lower_bound(first, last, v, [&](uint32_t h, uint32_t key) { return head(h) < key; });
    const auto* hi = std::upper_bound(lo, last, v, [&](uint32_t key, uint32_t h) { return key < head(h); });
    return {lo, hi};
  }

  std::vector<uint32_t> sorted_face(uint32_t f) const {
    auto corners = in.face(f);
    std::vector<uint32_t> s(corners.begin(), corners.end());
    std::sort(s.begin(), s.end());
    return s;
  }
};

// Offsets that match the index list, and counts that fit 32-bit ids (the fast path relies on both too).
void check_sizes(const PolygonMesh& in) {
  const size_t num_interior = in.indices.size();
  if (in.face_offsets.empty() || in.face_offsets.front() != 0 || in.face_offsets.back() != num_interior) {
    throw MeshError("polygon offsets do not match the index list");
  }
  if (in.num_vertices() >= kNone / 2 || num_interior >= kNone / 2 || in.num_faces() >= FaceId::kBoundaryBit) {
    throw MeshError("mesh too large: " + std::to_string(in.num_faces()) + " faces with " +
                    std::to_string(num_interior) + " corners exceed 32-bit ids");
  }
}

void check_faces(const PolygonMesh& in) {
  const size_t num_vertices = in.num_vertices();
  std::vector<uint32_t> sorted;
  for (size_t f = 0; f < in.num_faces(); ++f) {
    auto corners = in.face(f);
    if (corners.size() < 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(corners.size()) +
                      " corners; a face needs at least 3");
    }
    for (uint32_t v : corners) {
      if (v >= num_vertices) {
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                        ", but there are only " + std::to_string(num_vertices) + " vertices");
      }
    }
    sorted.assign(corners.begin(), corners.end());
    std::sort(sorted.begin(), sorted.end());
    auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end()) {
      throw MeshError(
          "face " + std::to_string(f) + " is degenerate: it uses vertex " + std::to_string(*repeated) + " twice",
          VertexId(*repeated));
    }
  }
}

Corners make_corners(const PolygonMesh& in) {
  Corners c{in, {}, {}, {}, {}};
  const size_t num_halfedges = in.indices.size();
  c.face_of.resize(num_halfedges);
  c.next.resize(num_halfedges);
  for (uint32_t f = 0; f < in.num_faces(); ++f) {
    const uint32_t begin = in.face_offsets[f], end = in.face_offsets[f + 1];
    for (uint32_t h = begin; h < end; ++h) {
      c.face_of[h] = f;
      c.next[h] = h + 1 < end ? h + 1 : begin;
    }
  }
  c.out_start.assign(in.num_vertices() + 1, 0);
  for (uint32_t v : in.indices) ++c.out_start[v + 1];
  for (size_t v = 0; v < in.num_vertices(); ++v) c.out_start[v + 1] += c.out_start[v];
  c.out.resize(num_halfedges);
  std::vector<uint32_t> cursor(c.out_start.begin(), c.out_start.end() - 1);
  for (uint32_t h = 0; h < num_halfedges; ++h) c.out[cursor[in.indices[h]]++] = h;
  for (size_t v = 0; v < in.num_vertices(); ++v) {
    auto first = c.out.begin() + c.out_start[v], last = c.out.begin() + c.out_start[v + 1];
    if (last - first > 1) std::sort(first, last, [&](uint32_t a, uint32_t b) { return c.head(a) < c.head(b); });
  }
  return c;
}

// Explains why the faces around edge u-v cannot form a manifold edge, and throws.
[[noreturn]] void refuse_edge(const Corners& c, uint32_t u, uint32_t v) {
  auto [fwd_lo, fwd_hi] = c.find(u, v);
  auto [rev_lo, rev_hi] = c.find(v, u);
  std::vector<uint32_t> faces;
  for (const auto* h = fwd_lo; h != fwd_hi; ++h) faces.push_back(c.face_of[*h]);
  for (const auto* h = rev_lo; h != rev_hi; ++h) faces.push_back(c.face_of[*h]);
  std::sort(faces.begin(), faces.end());
  for (size_t i = 0; i < faces.size(); ++i) {
    for (size_t j = i + 1; j < faces.size(); ++j) {
      if (c.sorted_face(faces[i]) == c.sorted_face(faces[j])) {
        throw MeshError("face " + std::to_string(faces[j]) + " repeats face " + std::to_string(faces[i]) +
                        " (same vertices)");
      }
    }
  }
  const std::string edge = "the edge between vertices " + std::to_string(u) + " and " + std::to_string(v);
  if (faces.size() > 2) {
    throw MeshError(edge + " is shared by " + std::to_string(faces.size()) + " faces (" + face_list(faces) +
                        "); a manifold edge has at most two",
                    VertexId(u));
  }
  throw MeshError("faces " + face_list(faces) + " both go from vertex " + std::to_string(u) + " to vertex " +
                      std::to_string(v) + ": their orientations are inconsistent (flip one of them)",
                  VertexId(u));
}

// Each interior halfedge's twin (the halfedge running the other way between the same vertices), kNone where there
// is none. Refuses an edge shared by more than two faces or walked the same way twice.
std::vector<uint32_t> match_twins(const PolygonMesh& in, const Corners& c) {
  std::vector<uint32_t> twin(in.indices.size(), kNone);
  for (uint32_t h = 0; h < in.indices.size(); ++h) {
    const uint32_t u = c.tail(h), v = c.head(h);
    auto [fwd_lo, fwd_hi] = c.find(u, v);
    auto [rev_lo, rev_hi] = c.find(v, u);
    const auto forward = fwd_hi - fwd_lo, reverse = rev_hi - rev_lo;
    if (forward > 1 || reverse > 1) refuse_edge(c, u, v);
    if (reverse == 1) twin[h] = *rev_lo;
  }
  return twin;
}

// Two faces glued along an edge with the same vertex set are one face repeated (a "pillow").
void refuse_pillows(const PolygonMesh& in, const Corners& c, const std::vector<uint32_t>& twin) {
  for (uint32_t h = 0; h < in.indices.size(); ++h) {
    const uint32_t t = twin[h];
    if (t == kNone || t < h) continue;
    const uint32_t f = c.face_of[h], g = c.face_of[t];
    if (in.face(f).size() != in.face(g).size()) continue;
    const bool same =
        in.face(f).size() == 3 ? c.head(c.next[h]) == c.head(c.next[t]) : c.sorted_face(f) == c.sorted_face(g);
    if (same) {
      throw MeshError("face " + std::to_string(std::max(f, g)) + " repeats face " + std::to_string(std::min(f, g)) +
                      " (same vertices, opposite orientation)");
    }
  }
}

// Per vertex, the halfedge without a twin that arrives there (kNone: none): boundary loops allow at most one.
std::vector<uint32_t> open_incoming_halfedges(const PolygonMesh& in, const Corners& c,
                                              const std::vector<uint32_t>& twin) {
  std::vector<uint32_t> open_incoming(in.num_vertices(), kNone);
  for (uint32_t h = 0; h < in.indices.size(); ++h) {
    if (twin[h] != kNone) continue;
    const uint32_t v = c.head(h);
    if (open_incoming[v] != kNone) {
      const uint32_t f = c.face_of[open_incoming[v]], g = c.face_of[h];
      throw MeshError("vertex " + std::to_string(v) + " is a bow-tie: faces " + std::to_string(f) + " and " +
                          std::to_string(g) + " touch only at this vertex, on two different holes",
                      VertexId(v));
    }
    open_incoming[v] = h;
  }
  return open_incoming;
}

// The interior halfedges and the faces, straight from the corners; the boundary halfedges' slots stay for
// finish_build.
void fill_interior(const PolygonMesh& in, const Corners& c, const std::vector<uint32_t>& twin,
                   std::span<const uint32_t> edge_of, size_t num_halfedges, HalfedgeMesh& mesh) {
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  m.h.resize(num_halfedges);
  m.h_alive.assign(num_halfedges, true);
  for (uint32_t h = 0; h < in.indices.size(); ++h) {
    m.h[h].next = HalfedgeId(c.next[h]);
    m.h[h].twin = HalfedgeId(twin[h]);
    m.h[h].vertex = VertexId(c.tail(h));
    m.h[h].edge = EdgeId(edge_of[h]);
    m.h[h].face = FaceId::face(c.face_of[h]);
  }
  m.f_halfedge.resize(in.num_faces());
  m.f_alive.assign(in.num_faces(), true);
  for (uint32_t f = 0; f < in.num_faces(); ++f) m.f_halfedge[f] = HalfedgeId(in.face_offsets[f]);
}

// A vertex whose fan does not reach all its halfedges joins several surfaces (a bow-tie).
void refuse_split_fans(const PolygonMesh& in, const Corners& c, const std::vector<uint32_t>& open_incoming,
                       const HalfedgeMesh& mesh) {
  for (uint32_t v = 0; v < in.num_vertices(); ++v) {
    if (!mesh.alive(VertexId(v))) continue;
    const uint32_t outgoing = c.out_start[v + 1] - c.out_start[v] + (open_incoming[v] != kNone ? 1 : 0);
    uint32_t walked = 0;
    mesh.for_each_outgoing(VertexId(v), [&](HalfedgeId) { ++walked; });
    if (walked == outgoing) continue;
    std::vector<uint32_t> fan;  // only on the error path: which faces the fan reached
    mesh.for_each_outgoing(VertexId(v), [&](HalfedgeId h) {
      if (!mesh.face(h).is_boundary()) fan.push_back(mesh.face(h).slot());
    });
    std::vector<uint32_t> others;
    for (uint32_t i = c.out_start[v]; i < c.out_start[v + 1]; ++i) {
      const uint32_t f = c.face_of[c.out[i]];
      if (std::find(fan.begin(), fan.end(), f) == fan.end()) others.push_back(f);
    }
    std::sort(fan.begin(), fan.end());
    std::sort(others.begin(), others.end());
    throw MeshError("vertex " + std::to_string(v) + " is a bow-tie: its faces form separate fans (faces " +
                        face_list(fan) + " on one, faces " + face_list(others) + " on another)",
                    VertexId(v));
  }
}

}  // namespace

namespace build_detail {

size_t finish_build(const PolygonMesh& in, std::span<const uint32_t> twin, std::span<const uint32_t> open_incoming,
                    HalfedgeMesh& mesh) {
  MeshStorage::Arrays m = MeshStorage::arrays(mesh);
  const auto num_interior = static_cast<uint32_t>(in.indices.size());
  const auto num_halfedges = static_cast<uint32_t>(m.h.size());
  HalfedgeRecord* records = m.h.data();

  // Walk each hole once, creating its boundary halfedges in walking order; each takes its twin's edge.
  std::vector<uint32_t> boundary_twin_of(num_halfedges > num_interior ? num_interior : 0, kNone);
  uint32_t next_boundary = num_interior;
  for (uint32_t start = 0; start < num_interior && next_boundary < num_halfedges; ++start) {
    if (twin[start] != kNone || boundary_twin_of[start] != kNone) continue;
    const FaceId loop = FaceId::boundary(static_cast<uint32_t>(m.b_halfedge.size()));
    m.b_halfedge.push_back(HalfedgeId(next_boundary));
    m.b_alive.push_back(true);
    uint32_t h = start;
    uint32_t previous = kNone;
    do {
      const uint32_t b = next_boundary++;
      boundary_twin_of[h] = b;
      records[h].twin = HalfedgeId(b);
      records[b].twin = HalfedgeId(h);
      records[b].vertex = records[records[h].next.index].vertex;  // h's head
      records[b].edge = records[h].edge;
      records[b].face = loop;
      if (previous != kNone) records[previous].next = HalfedgeId(b);
      previous = b;
      h = open_incoming[in.indices[h]];  // the open halfedge arriving where this one leaves
    } while (h != start);
    records[previous].next = m.b_halfedge.back();
  }

  // Each edge's first halfedge (number_edges).
  m.e_halfedge.reserve(num_halfedges / 2);
  for (uint32_t h = 0; h < num_interior; ++h) {
    if (records[h].edge.index == m.e_halfedge.size()) m.e_halfedge.push_back(HalfedgeId(h));
  }
  m.e_alive.assign(m.e_halfedge.size(), true);

  // Vertices: lowest outgoing halfedge, or the outgoing boundary halfedge.
  m.v_position.assign(in.positions.begin(), in.positions.end());
  m.v_halfedge.assign(in.num_vertices(), HalfedgeId());
  for (uint32_t h = 0; h < num_interior; ++h) {
    HalfedgeId& slot = m.v_halfedge[in.indices[h]];
    if (!slot.valid()) slot = HalfedgeId(h);
  }
  for (uint32_t b = num_interior; b < num_halfedges; ++b) m.v_halfedge[records[b].vertex.index] = HalfedgeId(b);
  m.v_alive.assign(in.num_vertices(), true);
  size_t unused = 0;
  for (size_t v = 0; v < in.num_vertices(); ++v) {
    if (m.v_halfedge[v].valid()) continue;
    m.v_alive.set(v, false);
    ++unused;
  }
  MeshStorage::count_live(mesh, unused);
  return unused;
}

HalfedgeMesh build_checked(const PolygonMesh& in, BuildReport* report) {
  check_sizes(in);
  check_faces(in);
  const Corners c = make_corners(in);
  const std::vector<uint32_t> twin = match_twins(in, c);
  refuse_pillows(in, c, twin);
  const std::vector<uint32_t> open_incoming = open_incoming_halfedges(in, c, twin);
  const size_t num_boundary = size_t(std::count(twin.begin(), twin.end(), kNone));
  const size_t num_halfedges = in.indices.size() + num_boundary;
  if (num_halfedges >= kNone / 2) throw MeshError("mesh too large for 32-bit halfedge ids");

  HalfedgeMesh mesh;
  const MeshArray<uint32_t> edge_of = number_edges(twin);
  fill_interior(in, c, twin, edge_of, num_halfedges, mesh);
  const size_t unused = finish_build(in, twin, open_incoming, mesh);
  refuse_split_fans(in, c, open_incoming, mesh);
  if (report) report->unused_vertices = unused;
  return mesh;
}

}  // namespace build_detail

HalfedgeMesh build_halfedge_mesh(const PolygonMesh& in, BuildReport* report) {
  check_sizes(in);
  HalfedgeMesh fast;
  size_t unused = 0;
  if (build_detail::build_fast(in, fast, unused)) {
    if (report) report->unused_vertices = unused;
    return fast;
  }
  return build_detail::build_checked(in, report);
}

PolygonMesh to_polygon_mesh(const HalfedgeMesh& mesh) {
  PolygonMesh out;
  std::vector<uint32_t> index_of(mesh.vertex_capacity(), kNone);
  out.positions.reserve(mesh.num_vertices());
  for (VertexId v : mesh.vertices()) index_of[v.index] = out.add_vertex(mesh.position(v));
  out.indices.reserve(mesh.num_halfedges());
  out.face_offsets.reserve(mesh.num_faces() + 1);
  for (FaceId f : mesh.faces()) {
    bool dead_vertex = false;
    const bool closed = mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
      const VertexId v = mesh.vertex(h);
      if (!mesh.alive(v)) {
        dead_vertex = true;
        return;
      }
      out.indices.push_back(index_of[v.index]);
    });
    if (!closed || dead_vertex) {
      throw MeshError(
          "cannot export " + format_id(f) + ": " + (closed ? "it uses a dead vertex" : "its next-cycle does not close"),
          f);
    }
    out.face_offsets.push_back(static_cast<uint32_t>(out.indices.size()));
  }
  return out;
}

}  // namespace meshedit
