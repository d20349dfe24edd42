// MeshRenderer: draws a HalfedgeMesh (faces, wireframe, boundary, vertices, halfedge arrows, hover,
// selection and "changed" colours) and picks the element under a pixel. Needs a current OpenGL 3.3 core
// context (a GLFW window's or an OffscreenContext) for its whole life.
//
// Per frame, the app calls:   update(mesh);  draw(camera, viewport, options, highlights);
// and on mouse moves:         pick(camera, viewport, x, y)
//
// Invariants and costs:
// - update() rebuilds GPU buffers only when it sees a different mesh object or a new mesh.version() (or,
//   as a safety net, different element counts); an idle frame does no per-element work on the CPU
//   (stats().uploads counts the rebuilds, so tests and the benchmark can prove it). A mesh object that
//   is assigned another mesh (opening a file into the same document) must not keep its old version:
//   call bump_version_above(old version) on it, or invalidate() here.
// - A selection or hover change only sets uniforms; a new `changed` list re-uploads one byte per element
//   of each kind; neither touches the geometry buffers.
// - draw() and pick() read the mesh given to the last update() for the few highlighted elements and,
//   when first asked for them, the halfedge arrows: that mesh must still exist (the app calls update()
//   every frame before draw(), so it always does).
// - A broken mesh (left so by a script) is drawn as far as it can be walked (mesh_geometry.h): faces
//   whose cycle does not close are skipped and counted, nothing loops or reads out of range.
// - Picking is exact: an id pass renders faces, then edges and halfedge arrows (when shown) as hairlines
//   and vertices as single pixels, into an R32UI buffer, with the same depth test as the picture; pick()
//   reads a small window around the cursor and prefers vertex > halfedge > edge > face within a few
//   pixels (pick_id.h); among the vertices seen, the one projecting nearest the cursor. The id
//   buffer is redrawn only when the camera, viewport, mesh or options changed since the last pick, so
//   hovering over a still view reads a few pixels only.
// - Edges and arrows are drawn over the faces without z-fighting: faces are pushed back with polygon
//   offset. draw() leaves depth testing on and binds program 0 and vertex array 0 when it returns; it
//   does not clear (the caller clears to style().background or its own colour).
#pragma once

#include <cstdint>
#include <memory>

#include "core/halfedge_mesh.h"
#include "render/camera.h"
#include "render/shader_library.h"
#include "render/view_options.h"

namespace meshedit {

struct RenderStats {
  uint64_t uploads = 0;            // geometry rebuilds by update()
  uint64_t arrow_uploads = 0;      // halfedge-arrow rebuilds (only while arrows are shown)
  uint64_t highlight_uploads = 0;  // rebuilds of the changed flags or the highlighted items
  uint64_t id_passes = 0;          // id-buffer redraws by pick()
  size_t triangles = 0, edges = 0, boundary_edges = 0, vertices = 0, arrows = 0;
  size_t skipped_faces = 0, skipped_edges = 0;  // live elements the last update could not draw
  size_t gpu_bytes = 0;                         // buffer memory the renderer holds
};

class MeshRenderer {
 public:
  // Builds the shader programs; throws RenderError if a shader is missing or does not compile.
  explicit MeshRenderer(const ShaderLibrary& shaders);
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;

  void update(const HalfedgeMesh& mesh);
  // Forces the next update() to rebuild, whatever the version says.
  void invalidate();
  void draw(const OrbitCamera& camera, Viewport viewport, const ViewOptions& options, const Highlights& highlights);
  // The element under pixel (x, y) (top-left origin, framebuffer pixels), or an invalid ElementRef for
  // the background, a pixel outside the viewport, or before any update(). Halfedges are pickable only
  // when the last draw() showed them. Restores the caller's framebuffer and viewport.
  ElementRef pick(const OrbitCamera& camera, Viewport viewport, int x, int y);

  // Bounding box of the uploaded mesh (for OrbitCamera::fit).
  const BoundingBox& bounds() const;
  const RenderStats& stats() const;
  RenderStyle& style();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshedit
