// Reference counts for the renderer's incremental updates (see mesh_references.h).
#include "render/mesh_references.h"

#include <algorithm>

namespace meshedit {
namespace {

// Adds `delta` (+1 or -1) for what live halfedge h (live edge e) of `mesh` points at.
// `Mesh`: a HalfedgeMesh, or the StateBefore of an edit.
template <class Mesh>
void count_halfedge(const Mesh& mesh, HalfedgeId h, MeshReferences& r, int delta) {
  if (!mesh.alive(h)) return;
  const VertexId v = mesh.vertex(h);
  if (v.index < r.outgoing.size()) r.outgoing[v.index] += uint32_t(delta);
  const HalfedgeId t = mesh.twin(h);
  if (t.index < r.twin_refs.size()) r.twin_refs[t.index] += uint32_t(delta);
}

template <class Mesh>
void count_edge(const Mesh& mesh, EdgeId e, MeshReferences& r, int delta) {
  if (!mesh.alive(e)) return;
  const HalfedgeId h = mesh.halfedge(e);
  if (h.index < r.edge_refs.size()) r.edge_refs[h.index] += uint32_t(delta);
}

template <class Before>
void apply_counts(MeshReferences& r, const Before& before, const HalfedgeMesh& after,
                  std::span<const uint32_t> halfedges, std::span<const uint32_t> edges) {
  // Take the listed slots' old pointers out, make room for either state's slots, put the new ones in, then drop
  // the slots `after` does not have (nothing live in `after` points there: such pointers are not counted).
  for (uint32_t h : halfedges) count_halfedge(before, HalfedgeId(h), r, -1);
  for (uint32_t e : edges) count_edge(before, EdgeId(e), r, -1);
  r.outgoing.resize(std::max<size_t>(r.outgoing.size(), after.vertex_capacity()), 0);
  r.twin_refs.resize(std::max<size_t>(r.twin_refs.size(), after.halfedge_capacity()), 0);
  r.edge_refs.resize(std::max<size_t>(r.edge_refs.size(), after.halfedge_capacity()), 0);
  for (uint32_t h : halfedges) count_halfedge(after, HalfedgeId(h), r, +1);
  for (uint32_t e : edges) count_edge(after, EdgeId(e), r, +1);
  r.outgoing.resize(after.vertex_capacity());
  r.twin_refs.resize(after.halfedge_capacity());
  r.edge_refs.resize(after.halfedge_capacity());
}

}  // namespace

MeshReferences MeshReferences::count(const HalfedgeMesh& mesh) {
  MeshReferences r;
  // Room for an eighth more, as the GPU buffers keep: splits then grow the counts without copying them.
  r.outgoing.reserve(mesh.vertex_capacity() + mesh.vertex_capacity() / 8 + 64);
  r.twin_refs.reserve(mesh.halfedge_capacity() + mesh.halfedge_capacity() / 8 + 64);
  r.edge_refs.reserve(mesh.halfedge_capacity() + mesh.halfedge_capacity() / 8 + 64);
  r.outgoing.assign(mesh.vertex_capacity(), 0);
  r.twin_refs.assign(mesh.halfedge_capacity(), 0);
  r.edge_refs.assign(mesh.halfedge_capacity(), 0);
  for (HalfedgeId h : mesh.halfedges()) count_halfedge(mesh, h, r, +1);
  for (EdgeId e : mesh.edges()) count_edge(mesh, e, r, +1);
  return r;
}

void MeshReferences::apply(const HalfedgeMesh& before, const HalfedgeMesh& after, std::span<const uint32_t> halfedges,
                           std::span<const uint32_t> edges) {
  apply_counts(*this, before, after, halfedges, edges);
}

void MeshReferences::apply(const StateBefore& before, const HalfedgeMesh& after, std::span<const uint32_t> halfedges,
                           std::span<const uint32_t> edges) {
  apply_counts(*this, before, after, halfedges, edges);
}

}  // namespace meshedit
