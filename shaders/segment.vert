// Line segments of any width, each drawn as two triangles spread across it in screen space (core
// profile has no wide lines). Used for mesh edges, halfedge arrows and overlay polylines.
// No vertex attributes: vertex gl_VertexID belongs to segment gl_VertexID / 6 (or / 2 as GL_LINES),
// read from a buffer texture.
// Colour and width come from the element's state (u_element_colours: selected, hovered, changed,
// boundary, else the base style) or, for overlays, from a style per segment. In the id pass
// (u_pick_width > 0) every segment has that width.

// Two texels per segment, the bits of an EdgeSegment: (start.xyz, end.x), (end.yz, id, flags).
uniform usamplerBuffer u_segments;
// One texel per segment for overlays: (RGBA8 colour, width in pixels as float bits).
uniform usamplerBuffer u_styles;
uniform mat4 u_view_projection;
uniform vec2 u_viewport;  // pixels
uniform bool u_element_colours;
uniform usamplerBuffer u_changed;
uniform uint u_selected;
uniform uint u_hovered;
uniform bool u_show_boundary;
uniform vec4 u_base_colour;
uniform vec4 u_boundary_colour;
uniform vec4 u_selected_colour;
uniform vec4 u_hovered_colour;
uniform vec4 u_changed_colour;
uniform float u_base_width;
uniform float u_boundary_width;
uniform float u_highlight_width;
uniform float u_pick_width;
uniform float u_cap;  // 1: extend both ends by half the width (so polylines join), 0: stop at the ends
// True when drawn as GL_LINES (two vertices per segment, one pixel wide: the cheap full wireframe);
// false for the two triangles per segment of any width.
uniform bool u_lines;

flat out vec4 v_colour;
flat out uint v_id;

// Corners of the two triangles: 0 and 1 at the start, 2 and 3 at the end; even on one side, odd on the other.
const int kCorners[6] = int[6](0, 1, 2, 2, 1, 3);

void main() {
  int per_segment = u_lines ? 2 : 6;
  int segment = gl_VertexID / per_segment;
  int corner = u_lines ? 2 * (gl_VertexID - segment * 2) : kCorners[gl_VertexID - segment * 6];
  uvec4 t0 = buffer_fetch(u_segments, 2 * segment);
  uvec4 t1 = buffer_fetch(u_segments, 2 * segment + 1);
  vec3 a_start = uintBitsToFloat(t0.xyz);
  vec3 a_end = uintBitsToFloat(uvec3(t0.w, t1.xy));
  uint a_id = t1.z;
  uint a_flags = t1.w;  // 1: boundary edge, 2: hidden (a slot with nothing to draw)
  if ((a_flags & 2u) != 0u) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing is drawn
    v_colour = vec4(0.0);
    v_id = 0xFFFFFFFFu;
    return;
  }

  vec4 colour;
  float width;
  if (!u_element_colours) {
    uvec2 style = buffer_fetch(u_styles, segment).xy;
    colour = vec4(uvec4(style.x, style.x >> 8, style.x >> 16, style.x >> 24) & 255u) / 255.0;
    width = uintBitsToFloat(style.y);
  } else {
    colour = u_base_colour;
    width = u_base_width;
    if (a_id == u_selected) {
      colour = u_selected_colour;
      width = u_highlight_width + 1.0;
    } else if (a_id == u_hovered) {
      colour = u_hovered_colour;
      width = u_highlight_width;
    } else if (buffer_fetch(u_changed, int(a_id)).r != 0u) {
      colour = u_changed_colour;
      width = u_highlight_width;
    } else if (u_show_boundary && (a_flags & 1u) != 0u) {
      colour = u_boundary_colour;
      width = u_boundary_width;
    }
  }
  if (u_pick_width > 0.0) width = u_pick_width;
  v_colour = colour;
  v_id = a_id;

  vec4 p0 = u_view_projection * vec4(a_start, 1.0);
  vec4 p1 = u_view_projection * vec4(a_end, 1.0);
  // Clip against the near plane first: a segment reaching behind the eye would project inside out.
  float d0 = p0.z + p0.w;
  float d1 = p1.z + p1.w;
  if (d0 < 0.0 && d1 < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: both triangles are dropped
    return;
  }
  if (d0 < 0.0) p0 = mix(p0, p1, d0 / (d0 - d1));
  if (d1 < 0.0) p1 = mix(p1, p0, d1 / (d1 - d0));

  vec2 half_viewport = 0.5 * u_viewport;
  vec2 s0 = p0.xy / p0.w * half_viewport;
  vec2 s1 = p1.xy / p1.w * half_viewport;
  vec2 along = s1 - s0;
  float length_px = length(along);
  along = length_px > 1e-6 ? along / length_px : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);

  bool at_end = corner >= 2;
  float side = (corner & 1) == 0 ? -1.0 : 1.0;
  vec4 p = at_end ? p1 : p0;
  if (u_lines) {
    gl_Position = p;
    return;
  }
  vec2 offset = across * side * 0.5 * width + along * (at_end ? 1.0 : -1.0) * u_cap * 0.5 * width;
  p.xy += offset / half_viewport * p.w;
  gl_Position = p;
}
