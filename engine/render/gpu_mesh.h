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
// - Where GLSL has no gl_PrimitiveID (GLES 3, render/gl_api.h), the positions, normals and both triangle lists are
//   also kept as buffer textures (pull_), written with the same bytes at the same offsets as their buffers, and the
//   faces are drawn without vertex arrays: shaders/face.vert pulls triangle t's corners by gl_VertexID.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
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
  // the program's `u_extra` uniform (at `extra_location`) to tell them apart. Binds u_extra_faces to `unit`, and
  // without gl_PrimitiveID the pulled corners, positions and normals to kPullUnits (the program's u_corners,
  // u_positions and u_normals).
  void draw_triangles(GLint extra_location, GLuint unit) const;
  static constexpr GLuint kPullUnits[3] = {4, 5, 6};

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
  // Without gl_PrimitiveID only: the face data again as buffer textures.
  struct Pull {
    BufferTexture corners{GL_RGB32UI}, extra_corners{GL_RGB32UI}, positions{GL_RGB32F}, normals{GL_RGB32F};
    VertexArray no_attributes = make_vertex_array();
  };
  std::unique_ptr<Pull> pull_;
  void draw_pulled_triangles(GLint extra_location, GLuint unit) const;
  size_t vertex_slots_ = 0, face_slots_ = 0;  // allocated
  size_t face_count_ = 0, extra_count_ = 0;   // in use (face slots, packed triangles)
};

// Slots to allocate for `n` in use.
inline size_t with_headroom(size_t n) { return n + n / 8 + 64; }

}  // namespace meshedit::gl
