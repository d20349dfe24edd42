// Internal to engine/render: the GPU copy of a SlotGeometry (slot_geometry.h) and of the slot arrows, with room to
// grow, so a patch (incremental_update.h) rewrites its slots in place (glBufferSubData of runs of consecutive slots)
// and appends new elements without reallocating.
//
// Invariants:
// - Every buffer holds, for each slot below the mesh's capacity, exactly what build_slot_geometry gives for it:
//   after upload(), and after each apply() of a patch made from the state it shows.
// - Allocations are the capacity plus an eighth (and a little): a mesh that grows by edits reallocates (a full
//   upload) once per eighth of its size. fits() says whether a patch needs more room than there is.
// - Draw calls cover the slots in use only; hidden slots draw nothing (0 0 0 triangles, flagged segments, invalid
//   point ids), so no per-frame work depends on what an edit left behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/gl_objects.h"
#include "render/gpu_batches.h"
#include "render/incremental_update.h"
#include "render/slot_geometry.h"

namespace meshedit::gl {

class GpuMesh {
 public:
  GpuMesh();

  void upload(const SlotGeometry& g);
  bool fits(const SlotPatch& patch) const;
  void apply(const SlotPatch& patch);  // precondition: fits(patch)

  void upload_arrows(const std::vector<EdgeSegment>& arrows);
  bool arrows_fit(const SlotPatch& patch) const { return size_t(patch.halfedge_capacity) * 3 <= arrows.capacity(); }
  void apply_arrows(const SlotPatch& patch);  // precondition: arrows_fit(patch)

  // Draws every face triangle of the bound program: the first triangle of each face slot (gl_PrimitiveID = the
  // face slot), then the packed later triangles of polygons (the face from u_extra_faces by gl_PrimitiveID), setting
  // the program's `u_extra` uniform (at `extra_location`) to tell them apart. Binds u_extra_faces to `unit`.
  void draw_triangles(GLint extra_location, GLuint unit) const;

  BufferTexture face_normals{GL_RGBA32F};
  SegmentBatch edges, boundary_edges, arrows;
  PointBatch points;

  size_t bytes() const;
  // Reads every buffer back into slot arrays (tests compare them with build_slot_geometry); `arrows` too when given.
  // Counts and bounds are not on the GPU and are left alone.
  void read(SlotGeometry& out, std::vector<EdgeSegment>* arrows) const;

 private:
  VertexArray face_vao_, extra_vao_;
  Buffer positions_, normals_, triangles_, extra_triangles_;
  BufferTexture extra_faces_{GL_R32UI};
  size_t vertex_slots_ = 0, face_slots_ = 0;  // allocated
  size_t face_count_ = 0, extra_count_ = 0;   // in use (face slots, packed triangles)
};

// Slots to allocate for `n` in use.
inline size_t with_headroom(size_t n) { return n + n / 8 + 64; }

}  // namespace meshedit::gl
