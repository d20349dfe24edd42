// The builder's two paths, used by build_halfedge_mesh (mesh_build.h): the fast one (mesh_build_fast.cpp) for
// input it can vouch for, and the checked one for everything else. Tests hold the two to the same result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "core/halfedge_mesh.h"
#include "core/mesh_array.h"
#include "core/mesh_build.h"
#include "core/polygon_mesh.h"

namespace meshedit::build_detail {

// Builds `mesh` from `in` exactly as the checked builder would (same ids, pointers, positions, liveness), and
// sets `unused_vertices`. Returns false, leaving `mesh` unspecified, as soon as the input is anything but a clean
// oriented manifold; the checked builder then runs and explains what is wrong. Never throws except bad_alloc.
bool build_fast(const PolygonMesh& in, HalfedgeMesh& mesh, size_t& unused_vertices);

// Each interior halfedge's edge, for the checked builder (write_face_halfedges numbers them the same way as it
// writes): edges are numbered in order of their first halfedge, and a halfedge is its edge's first when its twin is
// higher or open (the open one's twin, made by finish_build, comes after every interior halfedge). `twin` as
// finish_build takes it.
MeshArray<uint32_t> number_edges(std::span<const uint32_t> twin);

// The first step after the twins are known, for the fast builder and for subdivision's refine_mesh: halfedge h of
// face f is corner h of `in` (next around the face, twin from `twin`, its vertex, the edge number_edges(twin) gives
// it, face f), every face's halfedge its first corner's, all live; `num_halfedges` slots (the interior ones, then the
// boundary ones, left for finish_build to write in full).
void write_face_halfedges(const PolygonMesh& in, std::span<const uint32_t> twin, size_t num_halfedges,
                          HalfedgeMesh& mesh);

// What both builders do once every interior halfedge has its next, twin (kInvalidIndex when open), vertex, edge
// (number_edges) and face and every face its halfedge (mesh_build.cpp): boundary loops, each hole walked from its
// first open halfedge; the edges' halfedges; vertex positions, halfedges and liveness; live counts. `twin` holds the
// interior twins (kInvalidIndex when open), and open_incoming[v] the open halfedge arriving at v. Returns the number
// of input vertices no face uses.
size_t finish_build(const PolygonMesh& in, std::span<const uint32_t> twin, std::span<const uint32_t> open_incoming,
                    HalfedgeMesh& mesh);

// The checked builder (mesh_build.cpp): the reference result, and the MeshError that names what is wrong.
HalfedgeMesh build_checked(const PolygonMesh& in, BuildReport* report);

}  // namespace meshedit::build_detail
