// What the mesh view shows (ViewOptions, toggled by the app's keys), what it highlights (Highlights, from
// the selection and the last operation's diff) and how it looks (RenderStyle). Plain data, no GL.
//
// Colour meanings, kept the same in every pass so a student learns them once:
//   selected  yellow-white      hovered  magenta      changed by the last operation  orange
//   boundary edges  green       faces  blue-grey, their back sides  grey-red (an inside-out face shows)
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

#include "core/ids.h"

namespace meshedit {

struct ViewOptions {
  bool smooth_shading = false;  // Q: Phong from area-weighted vertex normals; else flat face normals
  bool wireframe = true;        // W: every edge as a line over the faces
  bool show_vertices = false;   // every vertex as a dot
  bool show_halfedges = false;  // every halfedge as an arrow inside its face (pickable only when shown)
  bool show_boundary = true;    // boundary edges in their own colour, even without the wireframe
  // Quality the app lowers while frames are slow (quality_governor.h):
  bool multisampling = true;  // use the framebuffer's samples, if it has any
  bool back_sides = true;     // draw back sides; off skips their pass, on a closed mesh only (none shows from outside)
};

// Hovered and selected are one element each (an invalid ElementRef for none); `changed` lists what the
// last operation touched. A boundary loop's ref is ignored (it has no area to colour).
// `changed` is not owned (the app points it at the document's list; it must outlive draw()). With a nonzero
// `changed_key`, equal keys promise an equal list (the app passes the document's last.serial), so a frame
// with the same key reads nothing of the list; with key 0 the renderer compares the list itself.
struct Highlights {
  ElementRef hovered;
  ElementRef selected;
  std::span<const ElementRef> changed;
  uint64_t changed_key = 0;
};

struct RenderStyle {
  glm::vec4 background{0.13f, 0.14f, 0.16f, 1.0f};
  glm::vec4 face{0.55f, 0.6f, 0.9f, 1.0f};
  glm::vec4 back_face{0.6f, 0.38f, 0.38f, 1.0f};
  glm::vec4 wire{0.07f, 0.07f, 0.09f, 1.0f};
  glm::vec4 boundary{0.15f, 0.85f, 0.35f, 1.0f};
  glm::vec4 vertex{0.95f, 0.95f, 0.95f, 1.0f};
  glm::vec4 arrow{0.95f, 0.95f, 0.85f, 1.0f};
  glm::vec4 selected{1.0f, 0.92f, 0.25f, 1.0f};
  glm::vec4 hovered{0.95f, 0.15f, 0.8f, 1.0f};
  glm::vec4 changed{1.0f, 0.55f, 0.1f, 1.0f};
  // Sizes in framebuffer pixels.
  float wire_width = 1.0f;
  float boundary_width = 2.5f;
  float highlight_width = 4.0f;
  float arrow_width = 1.5f;
  float vertex_size = 7.0f;
  float highlight_vertex_size = 11.0f;
  // Above this many triangles a mesh is "large": picked from a faces-only id pass (pick_from_faces.h), and the app
  // draws it at the quality governor's cheapest level until frames are measured (at a million triangles llvmpipe
  // takes most of a second for a frame at full quality). At or below it the governor starts at full quality.
  size_t large_mesh_triangles = 100000;
  // A cap on the texels of one buffer texture below OpenGL's own (GL_MAX_TEXTURE_BUFFER_SIZE, 128M on llvmpipe);
  // 0 for OpenGL's. Past it a mesh is too large to draw (MeshRenderer::update). Tests set it to try that cheaply.
  size_t max_buffer_texels = 0;
};

// Whether a mesh of this many triangles is large (see RenderStyle::large_mesh_triangles).
inline bool is_large_mesh(size_t triangles, const RenderStyle& style) { return triangles > style.large_mesh_triangles; }

}  // namespace meshedit
