// The slot buffers of a mesh vouched valid with triangle faces (see slot_geometry_proven.h for why no check is
// needed and what must stay identical to the general build).
#include "render/slot_geometry_proven.h"

namespace meshedit {

SlotGeometry build_slot_geometry_of_proven_triangles(const HalfedgeMesh& mesh) {
  SlotGeometry g;
  const uint32_t vertices = mesh.vertex_capacity(), faces = mesh.face_capacity(), edges = mesh.edge_capacity();
  g.positions.assign(vertices, glm::vec3(0.0f));
  g.points.assign(vertices, kHiddenPoint);
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    g.points[v.index] = {glm::vec3(p), v.index};
    g.positions[v.index] = g.points[v.index].position;
    g.bounds.add(p);
  }
  g.counts.vertices = mesh.num_vertices();

  MeshArray<glm::dvec3> sums(vertices, glm::dvec3(0.0));
  g.triangles.assign(size_t(faces) * 3, 0u);
  g.face_normals.assign(faces, glm::vec4(0.0f));
  for (FaceId f : mesh.faces()) {
    const HalfedgeRecord& r0 = mesh.record(mesh.halfedge(f));
    const HalfedgeRecord& r1 = mesh.record(r0.next);
    const HalfedgeRecord& r2 = mesh.record(r1.next);
    const uint32_t corners[3] = {r0.vertex.index, r1.vertex.index, r2.vertex.index};
    const glm::dvec3 term = cycle_term(mesh, corners, 3);
    const size_t slot = f.slot();
    g.triangles[3 * slot] = corners[0];
    g.triangles[3 * slot + 1] = corners[1];
    g.triangles[3 * slot + 2] = corners[2];
    g.face_normals[slot] = flat_normal(term);
    for (uint32_t c : corners) sums[c] += term;
  }
  g.counts.triangles = mesh.num_faces();
  g.smooth_normals.resize(vertices);
  for (uint32_t v = 0; v < vertices; ++v) g.smooth_normals[v] = glm::vec3(unit_or_zero(sums[v]));

  g.edges.assign(edges, kHiddenSegment);
  for (EdgeId e : mesh.edges()) {
    const HalfedgeRecord& h = mesh.record(mesh.halfedge(e));
    const HalfedgeRecord& t = mesh.record(h.twin);
    EdgeSegment& s = g.edges[e.index];
    s.start = glm::vec3(mesh.position(h.vertex));
    s.end = glm::vec3(mesh.position(t.vertex));
    s.edge = e.index;
    s.flags = h.face.is_boundary() || t.face.is_boundary() ? kEdgeBoundaryFlag : 0;
    if (s.flags & kEdgeBoundaryFlag) g.boundary_edges.push_back(e.index);
  }
  g.counts.edges = mesh.num_edges();
  return g;
}

}  // namespace meshedit
