// MeshRenderer: draws a HalfedgeMesh (faces, wireframe, boundary, vertices, halfedge arrows, hover,
// selection and "changed" colours) and picks the element under a pixel. Needs a current OpenGL 3.3 core
// context (a GLFW window's or an OffscreenContext) for its whole life.
//
// Per frame, the app calls:   update(mesh[, change]);  draw(camera, viewport, options, highlights);
// and on mouse moves:         pick(camera, viewport, x, y)
//
// Invariants and costs:
// - The GPU buffers are laid out by element slot (slot_geometry.h) and always hold exactly what a full build of
//   the last updated mesh state gives (tests compare them byte for byte after long runs of edits).
// - update() does nothing when it sees the mesh object and version it last saw (or, as a safety net, other
//   element counts mean a change): an idle frame or a camera move does no per-element work on the CPU and
//   uploads nothing (stats().uploads, patches and last_update_bytes prove it).
// - A change described by a MeshChange (the document's diff: the state before and every element that changed)
//   is applied in place: only the slots whose values change are recomputed and rewritten (glBufferSubData of
//   runs of slots), new elements go into room kept at the end, in time proportional to the edit, not the mesh
//   (incremental_update.h). Anything else, or a change the planner cannot certify (a broken mesh, a polygon
//   touched), is a full rebuild. A mesh object that is assigned another mesh (opening a file into the same
//   document) must not keep its old version: call bump_version_above(old version) on it, or invalidate() here.
// - A selection or hover change only sets uniforms; a new `changed` list rewrites the flag bytes of the elements
//   it and the previous list name; neither touches the geometry buffers. A list with the same nonzero key as the
//   last one is not read at all.
// - draw() and pick() read the mesh given to the last update() for the few highlighted elements and,
//   when first asked for them, the halfedge arrows: that mesh must still exist (the app calls update()
//   every frame before draw(), so it always does).
// - A broken mesh (left so by a script) is drawn as far as it can be walked (mesh_geometry.h): faces
//   whose cycle does not close are skipped and counted, nothing loops or reads out of range.
// - Picking is exact and redraws its id buffer only when the camera, viewport, mesh or options changed (pick()).
// - Edges and arrows are drawn over the faces without z-fighting: faces are pushed back with polygon offset.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"
#include "render/camera.h"
#include "render/shader_library.h"
#include "render/slot_geometry.h"
#include "render/view_options.h"

namespace meshedit {

struct RenderStats {
  uint64_t uploads = 0;                  // full geometry rebuilds by update()
  uint64_t patches = 0;                  // in-place updates by update() (a MeshChange it could apply)
  uint64_t arrow_uploads = 0;            // full halfedge-arrow rebuilds (only while arrows are shown)
  uint64_t highlight_uploads = 0;        // rebuilds of the changed flags or the highlighted items
  uint64_t id_passes = 0;                // id-buffer redraws by pick()
  uint64_t refusals = 0;                 // updates refused: the mesh too large to draw (then nothing is drawn)
  bool last_update_patch = false;        // the last update() that changed anything was a patch (not a full rebuild)
  size_t last_update_bytes = 0;          // bytes the last update() that changed anything sent to the GPU
  size_t last_update_slots = 0;          // slots it rewrote (every slot for a full rebuild)
  double last_id_pass_ms = 0.0;          // wall time of the last id-buffer redraw (to glFinish)
  bool last_id_pass_faces_only = false;  // it drew faces only (a large mesh: pick_from_faces.h)
  std::string last_rebuild_reason;       // why the last full rebuild was not a patch ("no change description", ...)
  size_t triangles = 0, edges = 0, boundary_edges = 0, vertices = 0;  // drawn
  size_t arrows = 0;                                                  // halfedge slots in the arrow batch (when built)
  size_t skipped_faces = 0, skipped_edges = 0;                        // live elements the last update could not draw
  size_t gpu_bytes = 0;                                               // buffer memory the renderer holds
  bool multisampled = false;                                          // the last draw() used multisampling
  int framebuffer_samples = 0;  // samples of the framebuffer the last draw() drew into (at first: the one bound then)
};

// No boundary edge and no face left undrawn: no back side shows from outside (ViewOptions::back_sides).
inline bool is_closed(const RenderStats& stats) { return stats.boundary_edges == 0 && stats.skipped_faces == 0; }

class MeshRenderer {
 public:
  // Builds the shader programs; throws RenderError if a shader is missing or does not compile.
  explicit MeshRenderer(const ShaderLibrary& shaders);
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;

  // What changed since the state the renderer last saw: that state, as a copy (`before`) or as the edit's patch
  // (`patch`, which ends in the mesh given to update(); then the state before is read through it, and nothing needs
  // a copy of the mesh), `elements` every element with a field that differs (each once), and the versions of the
  // updated mesh object before and after. update() trusts it only when the versions and element counts match what
  // it holds.
  struct MeshChange {
    const HalfedgeMesh* before = nullptr;
    std::span<const ElementRef> elements;
    uint64_t version_before = 0, version_after = 0;
    const MeshPatch* patch = nullptr;  // used when `before` is null
  };
  // Throws RenderError when the mesh is too large to draw (a buffer texture would need more texels than OpenGL, or
  // RenderStyle::max_buffer_texels, allows), found from the capacities before any whole-mesh work; then nothing is
  // drawn or picked until an update() succeeds.
  void update(const HalfedgeMesh& mesh, const MeshChange* change = nullptr);
  // A full upload of `mesh` whose smooth shading uses `smooth_normals` (by vertex slot; unit vectors, or zero where
  // the shader falls back to the flat normal) instead of the area-weighted normals: a student's vertex_normal drawn
  // as the renderer draws its own. Kept until the mesh changes (update() of the same state does nothing).
  void update_with_normals(const HalfedgeMesh& mesh, std::span<const glm::vec3> smooth_normals);
  // Forces the next update() to rebuild, whatever the version says.
  void invalidate();
  // ViewOptions::multisampling off draws single-sampled, whatever the framebuffer has; ViewOptions::back_sides off
  // skips the pass that shows back sides when the mesh is closed (is_closed), in the picture and the id pass alike.
  // Leaves depth testing on and binds program 0 and vertex array 0 when it returns; does not clear (the caller
  // clears to style().background or its own colour).
  void draw(const OrbitCamera& camera, Viewport viewport, const ViewOptions& options, const Highlights& highlights);
  // The element under pixel (x, y) (top-left origin, framebuffer pixels), or an invalid ElementRef for
  // the background, a pixel outside the viewport, or before any update(). Halfedges are pickable only
  // when the last draw() showed them. Restores the caller's framebuffer and viewport.
  // An id pass renders faces, then edges and halfedge arrows (when shown) as hairlines and vertices as single
  // pixels, into an R32UI buffer, with the same depth test as the picture; pick() reads a small window around the
  // cursor and prefers vertex > halfedge > edge > face within a few pixels (pick_id.h); among the vertices seen, the
  // one projecting nearest the cursor. A large mesh whose live faces and edges are all drawn gets a faces-only id
  // pass (a third of the cost) and its vertices, edges and arrows are found on the CPU from the faces seen around
  // the cursor (pick_from_faces.h). The id buffer is redrawn only when the camera, viewport, mesh or options changed
  // since the last pick, so hovering over a still view reads a few pixels only.
  ElementRef pick(const OrbitCamera& camera, Viewport viewport, int x, int y);
  // True when pick() at this camera and viewport would only read pixels (the id buffer is current): the app waits
  // for the mouse to rest after a camera move before it hovers.
  bool pick_is_cheap(const OrbitCamera& camera, Viewport viewport) const;

  // The GPU buffers read back in slot layout (tests: they must equal build_slot_geometry of the mesh), with the
  // arrows when they are built (else `arrows` is emptied). Slow; not for frames.
  void read_gpu_buffers(SlotGeometry& out, std::vector<EdgeSegment>& arrows) const;

  // Bounding box of the uploaded mesh (for OrbitCamera::fit).
  const BoundingBox& bounds() const;
  const RenderStats& stats() const;
  RenderStyle& style();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshedit
