// The slot layout of the renderer's buffers (see slot_geometry.h for the rules).
//
// Invariant: the whole-mesh build and the one-slot functions compute each value with the same operations in the
// same order, so an incremental update that recomputes some slots gets exactly the bytes a full build would.
#include "render/slot_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/finite.h"
#include "core/parallel_for.h"

namespace meshedit {
namespace {

// Area below this fraction of the squared size of the face counts as zero (core/normals.cpp's rule).
constexpr double kZeroAreaRelative = 1e-14;

// Twice the vector area of a closed cycle, as core's face_term computes it. `Mesh`: a HalfedgeMesh, or the
// StateBefore of an edit (the same arithmetic, so the same bits).
template <class Mesh>
glm::dvec3 cycle_term(const Mesh& mesh, const std::vector<uint32_t>& corners) {
  glm::dvec3 out(0.0), previous(0.0);
  const glm::dvec3 origin = mesh.position(VertexId(corners[0]));
  double size_sq = 0.0;
  for (size_t i = 1; i < corners.size(); ++i) {
    const glm::dvec3 p = mesh.position(VertexId(corners[i])) - origin;
    out += glm::cross(previous, p);
    size_sq = std::max(size_sq, glm::dot(p, p));
    previous = p;
  }
  if (!(glm::length(out) > kZeroAreaRelative * size_sq)) out = glm::dvec3(0.0);
  return out;
}

template <class Mesh>
void draw_face_of(const Mesh& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
                  std::vector<uint8_t>* visited, uint32_t max_steps) {
  out.corners.clear();
  out.term = glm::dvec3(0.0);
  out.walk = walk_face_cycle(mesh, f, cycle, visited, max_steps);
  if (!out.drawn()) return;
  for (HalfedgeId h : cycle) out.corners.push_back(mesh.vertex(h).index);
  out.term = cycle_term(mesh, out.corners);
}

template <class Mesh>
VertexPoint point_of(const Mesh& mesh, VertexId v) {
  if (!mesh.alive(v) || !finite(mesh.position(v))) return kHiddenPoint;
  return {glm::vec3(mesh.position(v)), v.index};
}

template <class Mesh>
EdgeSegment edge_of(const Mesh& mesh, EdgeId e) {
  const std::optional<EdgeSegment> s = edge_segment(mesh, e);
  return s ? *s : kHiddenSegment;
}

}  // namespace

glm::vec4 flat_normal(const glm::dvec3& term) { return glm::vec4(glm::vec3(unit_or_zero(term)), 0.0f); }

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
  const double length = glm::length(v);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  return v / length;
}

void draw_face(const HalfedgeMesh& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
               std::vector<uint8_t>* visited, uint32_t max_steps) {
  draw_face_of(mesh, f, out, cycle, visited, max_steps);
}

void draw_face(const StateBefore& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
               std::vector<uint8_t>* visited, uint32_t max_steps) {
  draw_face_of(mesh, f, out, cycle, visited, max_steps);
}

VertexPoint slot_point(const HalfedgeMesh& mesh, VertexId v) { return point_of(mesh, v); }
VertexPoint slot_point(const StateBefore& mesh, VertexId v) { return point_of(mesh, v); }

EdgeSegment slot_edge(const HalfedgeMesh& mesh, EdgeId e) { return edge_of(mesh, e); }
EdgeSegment slot_edge(const StateBefore& mesh, EdgeId e) { return edge_of(mesh, e); }

std::array<EdgeSegment, 3> slot_arrow(const HalfedgeMesh& mesh, HalfedgeId h) {
  const std::optional<HalfedgeArrow> a = halfedge_arrow(mesh, h);
  if (!a) return {kHiddenSegment, kHiddenSegment, kHiddenSegment};
  return {EdgeSegment{a->tail, a->tip, a->halfedge, 0}, EdgeSegment{a->tip, a->barb_inner, a->halfedge, 0},
          EdgeSegment{a->tip, a->barb_outer, a->halfedge, 0}};
}

glm::vec3 smooth_normal(uint32_t vertex, std::vector<CornerFace>& faces) {
  std::sort(faces.begin(), faces.end(), [](const CornerFace& a, const CornerFace& b) { return a.face < b.face; });
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < faces.size(); ++i) {
    if (i > 0 && faces[i].face == faces[i - 1].face) continue;
    const FaceDraw& d = *faces[i].draw;
    for (uint32_t c : d.corners) {
      if (c == vertex) sum += d.term;
    }
  }
  return glm::vec3(unit_or_zero(sum));
}

namespace {

// One chunk's share of the counts, the bounds and the lists kept in id order, merged in chunk order.
struct ChunkResult {
  SlotCounts counts;
  BoundingBox bounds;
  std::vector<uint32_t> extra_triangles, extra_faces, boundary_edges;
};

void append(std::vector<uint32_t>& to, const std::vector<uint32_t>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

void merge(SlotGeometry& g, const std::vector<ChunkResult>& chunks) {
  for (const ChunkResult& c : chunks) {
    g.counts.triangles += c.counts.triangles;
    g.counts.skipped_faces += c.counts.skipped_faces;
    g.counts.edges += c.counts.edges;
    g.counts.skipped_edges += c.counts.skipped_edges;
    g.counts.vertices += c.counts.vertices;
    if (!c.bounds.empty()) {
      g.bounds.add(c.bounds.min);
      g.bounds.add(c.bounds.max);
    }
    append(g.extra_triangles, c.extra_triangles);
    append(g.extra_faces, c.extra_faces);
    append(g.boundary_edges, c.boundary_edges);
  }
}

// fn(out, begin, end) over [0, n) in parallel_chunks' fixed chunks, each with its own result, merged into g in
// chunk order (so lists stay in id order).
template <class Fn>
void run_chunks(SlotGeometry& g, int threads, size_t n, Fn&& fn) {
  std::vector<ChunkResult> chunks(chunk_count(threads, n));
  parallel_chunks(threads, n, [&](size_t chunk, size_t begin, size_t end) { fn(chunks[chunk], begin, end); });
  merge(g, chunks);
}

// Vertex slots: point, position, bounds.
void build_vertex_slots(const HalfedgeMesh& mesh, int threads, SlotGeometry& g) {
  const uint32_t vertices = mesh.vertex_capacity();
  resize_for_overwrite(g.points, vertices);
  resize_for_overwrite(g.positions, vertices);
  run_chunks(g, threads, vertices, [&](ChunkResult& out, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const VertexId v(static_cast<uint32_t>(i));
      const VertexPoint point = slot_point(mesh, v);
      g.points[i] = point;
      g.positions[i] = point.vertex == kInvalidIndex ? glm::vec3(0.0f) : point.position;
      if (point.vertex == kInvalidIndex) continue;
      out.bounds.add(mesh.position(v));
      ++out.counts.vertices;
    }
  });
}

// Face slots: the first fan triangle and the flat normal (zero where not drawn), each drawn face's term and the
// later fan triangles of polygons. A walk marks only halfedges whose face is the walked face (walk_face_cycle
// stops at any other), so walks of different faces share no byte of `visited` and run on any thread.
void build_face_slots(const HalfedgeMesh& mesh, int threads, SlotGeometry& g, MeshArray<glm::dvec3>& terms,
                      MeshArray<uint8_t>& drawn) {
  const uint32_t faces = mesh.face_capacity();
  resize_for_overwrite(g.triangles, size_t(faces) * 3);
  resize_for_overwrite(g.face_normals, faces);
  resize_for_overwrite(terms, faces);
  resize_for_overwrite(drawn, faces);
  std::vector<uint8_t> visited(mesh.halfedge_capacity(), 0);
  run_chunks(g, threads, faces, [&](ChunkResult& out, size_t begin, size_t end) {
    std::vector<HalfedgeId> cycle;
    FaceDraw d;
    for (size_t slot = begin; slot < end; ++slot) {
      const FaceId f = FaceId::face(static_cast<uint32_t>(slot));
      const bool alive = mesh.alive(f);
      if (alive) draw_face(mesh, f, d, cycle, &visited);
      drawn[slot] = alive && d.drawn();
      if (!drawn[slot]) {
        out.counts.skipped_faces += alive ? 1 : 0;
        g.triangles[3 * slot] = g.triangles[3 * slot + 1] = g.triangles[3 * slot + 2] = 0;
        g.face_normals[slot] = glm::vec4(0.0f);
        continue;
      }
      g.triangles[3 * slot] = d.corners[0];
      g.triangles[3 * slot + 1] = d.corners[1];
      g.triangles[3 * slot + 2] = d.corners[2];
      for (size_t i = 2; i + 1 < d.corners.size(); ++i) {
        out.extra_triangles.insert(out.extra_triangles.end(), {d.corners[0], d.corners[i], d.corners[i + 1]});
        out.extra_faces.push_back(uint32_t(slot));
      }
      out.counts.triangles += d.triangle_count();
      g.face_normals[slot] = flat_normal(d.term);
      terms[slot] = d.term;
    }
  });
}

// Smooth normals: each vertex's sum takes the terms of the drawn faces it is a corner of in face id order, once
// per corner (a drawn face's corners are its first triangle, then the last corner of each later fan triangle).
// Each chunk owns a range of vertices and reads every face in order, adding only to its own vertices, so every sum
// is made in the same order on any number of threads.
void build_smooth_normals(const HalfedgeMesh& mesh, int threads, const MeshArray<glm::dvec3>& terms,
                          const MeshArray<uint8_t>& drawn, SlotGeometry& g) {
  const uint32_t vertices = mesh.vertex_capacity(), faces = mesh.face_capacity();
  resize_for_overwrite(g.smooth_normals, vertices);
  MeshArray<glm::dvec3> sums;
  resize_for_overwrite(sums, vertices);
  parallel_chunks(threads, vertices, [&](size_t, size_t begin, size_t end) {
    std::fill(sums.begin() + begin, sums.begin() + end, glm::dvec3(0.0));
    const auto add = [&](uint32_t corner, const glm::dvec3& term) {
      if (corner >= begin && corner < end) sums[corner] += term;
    };
    size_t extra = 0;
    for (uint32_t f = 0; f < faces; ++f) {
      if (!drawn[f]) continue;
      const glm::dvec3& term = terms[f];
      add(g.triangles[size_t(3) * f], term);
      add(g.triangles[size_t(3) * f + 1], term);
      add(g.triangles[size_t(3) * f + 2], term);
      for (; extra < g.extra_faces.size() && g.extra_faces[extra] == f; ++extra) {
        add(g.extra_triangles[3 * extra + 2], term);
      }
    }
    for (size_t v = begin; v < end; ++v) g.smooth_normals[v] = glm::vec3(unit_or_zero(sums[v]));
  });
}

// Edge slots: the segment, or a hidden one.
void build_edge_slots(const HalfedgeMesh& mesh, int threads, SlotGeometry& g) {
  const uint32_t edges = mesh.edge_capacity();
  resize_for_overwrite(g.edges, edges);
  run_chunks(g, threads, edges, [&](ChunkResult& out, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const EdgeId e(static_cast<uint32_t>(i));
      g.edges[i] = slot_edge(mesh, e);
      if (hidden(g.edges[i])) {
        out.counts.skipped_edges += mesh.alive(e) ? 1 : 0;
        continue;
      }
      ++out.counts.edges;
      if (g.edges[i].flags & kEdgeBoundaryFlag) out.boundary_edges.push_back(uint32_t(i));
    }
  });
}

}  // namespace

SlotGeometry build_slot_geometry(const HalfedgeMesh& mesh, int threads) {
  SlotGeometry g;
  build_vertex_slots(mesh, threads, g);
  MeshArray<glm::dvec3> terms;
  MeshArray<uint8_t> drawn;
  build_face_slots(mesh, threads, g, terms, drawn);
  build_smooth_normals(mesh, threads, terms, drawn, g);
  build_edge_slots(mesh, threads, g);
  return g;
}

std::vector<EdgeSegment> build_slot_arrows(const HalfedgeMesh& mesh) {
  std::vector<EdgeSegment> out(size_t(mesh.halfedge_capacity()) * 3, kHiddenSegment);
  std::vector<uint8_t> visited(mesh.halfedge_capacity(), 0);
  std::vector<HalfedgeId> cycle;
  std::vector<HalfedgeArrow> arrows;
  for (FaceId f : mesh.faces()) {
    if (walk_face_cycle(mesh, f, cycle, &visited, kInvalidIndex) != FaceWalk::Closed) continue;
    arrows.clear();
    add_cycle_arrows(mesh, cycle, arrows);
    for (const HalfedgeArrow& a : arrows) {
      EdgeSegment* slot = &out[size_t(a.halfedge) * 3];
      slot[0] = {a.tail, a.tip, a.halfedge, 0};
      slot[1] = {a.tip, a.barb_inner, a.halfedge, 0};
      slot[2] = {a.tip, a.barb_outer, a.halfedge, 0};
    }
  }
  return out;
}

}  // namespace meshedit
