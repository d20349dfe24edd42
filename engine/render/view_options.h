// What the mesh view shows (ViewOptions, toggled by the app's keys), what it highlights (Highlights, from
// the selection and the last operation's diff) and how it looks (RenderStyle). Plain data, no GL.
//
// Colours come from the palette (core/palette.h), the one place their meanings are named: set_render_colours()
// copies a palette's into a RenderStyle, and a default RenderStyle has the dark theme's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

#include "core/ids.h"
#include "core/palette.h"

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
  glm::vec4 background{palette_for(Theme::Dark).neutrals.view, 1.0f};
  glm::vec4 face{palette_for(Theme::Dark).neutrals.face, 1.0f};
  glm::vec4 back_face{palette_for(Theme::Dark).neutrals.back_face, 1.0f};
  glm::vec4 wire{palette_for(Theme::Dark).neutrals.wire, 1.0f};
  glm::vec4 boundary{palette_for(Theme::Dark).boundary, 1.0f};
  glm::vec4 vertex{palette_for(Theme::Dark).vertex, 1.0f};
  glm::vec4 arrow{palette_for(Theme::Dark).arrow, 1.0f};
  glm::vec4 selected{palette_for(Theme::Dark).selected, 1.0f};
  glm::vec4 hovered{palette_for(Theme::Dark).hovered, 1.0f};
  glm::vec4 changed{palette_for(Theme::Dark).changed, 1.0f};
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

// Sets the style's colours to the palette's (its sizes and limits are left as they are).
inline void set_render_colours(RenderStyle& style, const Palette& palette) {
  style.background = glm::vec4(palette.neutrals.view, 1.0f);
  style.face = glm::vec4(palette.neutrals.face, 1.0f);
  style.back_face = glm::vec4(palette.neutrals.back_face, 1.0f);
  style.wire = glm::vec4(palette.neutrals.wire, 1.0f);
  style.boundary = glm::vec4(palette.boundary, 1.0f);
  style.vertex = glm::vec4(palette.vertex, 1.0f);
  style.arrow = glm::vec4(palette.arrow, 1.0f);
  style.selected = glm::vec4(palette.selected, 1.0f);
  style.hovered = glm::vec4(palette.hovered, 1.0f);
  style.changed = glm::vec4(palette.changed, 1.0f);
}

// A RenderStyle with the theme's colours and the default sizes.
inline RenderStyle render_style_for(Theme theme) {
  RenderStyle style;
  set_render_colours(style, palette_for(theme));
  return style;
}

// Whether a mesh of this many triangles is large (see RenderStyle::large_mesh_triangles).
inline bool is_large_mesh(size_t triangles, const RenderStyle& style) { return triangles > style.large_mesh_triangles; }

}  // namespace meshedit
