// The slot layout of the renderer's buffers (see slot_geometry.h for the rules).
//
// Invariant: the whole-mesh build and the one-slot functions compute each value with the same operations in the
// same order, so an incremental update that recomputes some slots gets exactly the bytes a full build would.
#include "render/slot_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/finite.h"

namespace meshedit {
namespace {

// Area below this fraction of the squared size of the face counts as zero (core/normals.cpp's rule).
constexpr double kZeroAreaRelative = 1e-14;

// Twice the vector area of a closed cycle, as core's face_term computes it.
glm::dvec3 cycle_term(const HalfedgeMesh& mesh, const std::vector<uint32_t>& corners) {
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

}  // namespace

glm::vec4 flat_normal(const glm::dvec3& term) { return glm::vec4(glm::vec3(unit_or_zero(term)), 0.0f); }

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
  const double length = glm::length(v);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  return v / length;
}

void draw_face(const HalfedgeMesh& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
               std::vector<uint8_t>* visited, uint32_t max_steps) {
  out.corners.clear();
  out.term = glm::dvec3(0.0);
  out.walk = walk_face_cycle(mesh, f, cycle, visited, max_steps);
  if (!out.drawn()) return;
  for (HalfedgeId h : cycle) out.corners.push_back(mesh.vertex(h).index);
  out.term = cycle_term(mesh, out.corners);
}

VertexPoint slot_point(const HalfedgeMesh& mesh, VertexId v) {
  if (!mesh.alive(v) || !finite(mesh.position(v))) return kHiddenPoint;
  return {glm::vec3(mesh.position(v)), v.index};
}

EdgeSegment slot_edge(const HalfedgeMesh& mesh, EdgeId e) {
  const std::optional<EdgeSegment> s = edge_segment(mesh, e);
  return s ? *s : kHiddenSegment;
}

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

SlotGeometry build_slot_geometry(const HalfedgeMesh& mesh) {
  SlotGeometry g;
  const uint32_t vertices = mesh.vertex_capacity(), faces = mesh.face_capacity(), edges = mesh.edge_capacity();
  g.positions.assign(vertices, glm::vec3(0.0f));
  g.points.assign(vertices, kHiddenPoint);
  for (VertexId v : mesh.vertices()) {
    g.points[v.index] = slot_point(mesh, v);
    if (g.points[v.index].vertex == kInvalidIndex) continue;
    g.positions[v.index] = g.points[v.index].position;
    g.bounds.add(mesh.position(v));
    ++g.counts.vertices;
  }

  MeshArray<glm::dvec3> sums(vertices, glm::dvec3(0.0));
  g.triangles.assign(size_t(faces) * 3, 0u);
  g.face_normals.assign(faces, glm::vec4(0.0f));
  std::vector<uint8_t> visited(mesh.halfedge_capacity(), 0);
  std::vector<HalfedgeId> cycle;
  FaceDraw d;
  for (FaceId f : mesh.faces()) {
    draw_face(mesh, f, d, cycle, &visited);
    if (!d.drawn()) {
      ++g.counts.skipped_faces;
      continue;
    }
    const size_t slot = f.slot();
    g.triangles[3 * slot] = d.corners[0];
    g.triangles[3 * slot + 1] = d.corners[1];
    g.triangles[3 * slot + 2] = d.corners[2];
    for (size_t i = 2; i + 1 < d.corners.size(); ++i) {
      g.extra_triangles.insert(g.extra_triangles.end(), {d.corners[0], d.corners[i], d.corners[i + 1]});
      g.extra_faces.push_back(uint32_t(slot));
    }
    g.counts.triangles += d.triangle_count();
    g.face_normals[slot] = flat_normal(d.term);
    for (uint32_t c : d.corners) sums[c] += d.term;
  }
  g.smooth_normals.resize(vertices);
  for (uint32_t v = 0; v < vertices; ++v) g.smooth_normals[v] = glm::vec3(unit_or_zero(sums[v]));

  g.edges.assign(edges, kHiddenSegment);
  for (EdgeId e : mesh.edges()) {
    g.edges[e.index] = slot_edge(mesh, e);
    if (hidden(g.edges[e.index])) {
      ++g.counts.skipped_edges;
      continue;
    }
    ++g.counts.edges;
    if (g.edges[e.index].flags & kEdgeBoundaryFlag) g.boundary_edges.push_back(e.index);
  }
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
