// TriangleRows: every face of a triangle mesh as one row, its three corners (in the face's own order, from its
// halfedge) and its id, in an order that keeps faces that share vertices close together. Loop subdivision leaves
// them on the mesh it makes: each face's four children take four consecutive rows, in the order the rows of the
// faces before had (or face id order when there were none), so after a few levels the rows walk the surface patch
// by patch while the stable ids scatter neighbours across the arrays. A whole-mesh pass that reads the rows
// (vertex_normals) then finds each vertex in cache for all of its faces.
//
// A pass on several threads gives each thread one run of consecutive rows; the vertices that more than one run
// touches (the seam between the runs' patches) need their terms added in order after the runs. The rows keep the
// seam they were last asked for, so a pass repeated on the same connectivity (normals while vertices move) finds it
// made.
//
// Invariants: the rows list every live face exactly once, with the corners its halfedge cycle has; a mesh keeps its
// rows only while its connectivity is the one they were made from (HalfedgeMesh::triangle_rows): every mutation
// other than a position, and every direct access through MeshStorage, drops them. Rows are immutable once made
// (the kept seam is derived from them alone), so copies of a mesh share them, from any thread.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>

#include "core/ids.h"
#include "core/mesh_array.h"

namespace meshedit {

struct TriangleRow {
  VertexId corner[3];  // the face's corners, from its halfedge's tail in next order
  FaceId face;
};

static_assert(sizeof(TriangleRow) == 16, "four rows fill one 64-byte cache line (Loop writes them so)");

// One bit per vertex slot: bit (i & 63) of word i >> 6 for vertex i.
using VertexBits = MeshArray<uint64_t>;

inline bool vertex_bit(const uint64_t* bits, VertexId v) { return (bits[v.index >> 6] >> (v.index & 63)) & 1u; }
inline void set_vertex_bit(uint64_t* bits, VertexId v) { bits[v.index >> 6] |= uint64_t(1) << (v.index & 63); }

// The rows themselves are the array (Loop fills it through MeshArray's interface before it is shared).
class TriangleRows : public MeshArray<TriangleRow> {
 public:
  TriangleRows() = default;
  TriangleRows(const TriangleRows&) = delete;
  TriangleRows& operator=(const TriangleRows&) = delete;

  // The vertices, of slots [0, vertices), that rows of more than one run touch, for the runs
  // parallel_chunks(threads, size()) cuts the rows into; none (all bits clear) for a single run. Made on `threads`
  // threads on the first call for a run count and vertex count, then kept until another is asked for.
  std::shared_ptr<const VertexBits> seam_between_runs(int threads, size_t vertices) const;

  // The rows' bytes and the kept seam's.
  size_t memory_bytes() const;

 private:
  struct Seam {
    size_t runs = 0, vertices = 0;
    std::shared_ptr<const VertexBits> bits;
  };
  mutable std::mutex seam_mutex_;  // guards seam_
  mutable Seam seam_;
};

}  // namespace meshedit
