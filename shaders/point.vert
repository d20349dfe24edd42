// Points (mesh vertices, overlay points) as round sprites of a size in pixels. Colour and size come
// from the element's state (u_element_colours) or per-point attributes (overlays); in the id pass
// (u_pick_size > 0) every point has that size.
layout(location = 0) in vec3 a_position;
layout(location = 1) in uint a_id;
layout(location = 2) in vec4 a_colour;  // overlays
layout(location = 3) in float a_size;   // overlays, pixels

uniform mat4 u_view;
uniform mat4 u_projection;
// World size of one pixel at unit view depth (2 / (projection[1][1] * viewport height)). Each point is
// moved towards the eye by as much depth as its own radius spans on screen, so the faces around a
// corner do not cut half of its dot away.
uniform float u_pixel_scale;
uniform bool u_element_colours;
uniform usamplerBuffer u_changed;
uniform uint u_selected;
uniform uint u_hovered;
uniform vec4 u_base_colour;
uniform vec4 u_selected_colour;
uniform vec4 u_hovered_colour;
uniform vec4 u_changed_colour;
uniform float u_base_size;
uniform float u_highlight_size;
uniform float u_pick_size;
// Mesh points sit at their vertex slot; a slot with nothing to draw has the invalid id and is skipped.
uniform bool u_hide_invalid;

flat out vec4 v_colour;
flat out uint v_id;

void main() {
  if (u_hide_invalid && a_id == 0xFFFFFFFFu) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
    gl_PointSize = 1.0;
    v_colour = vec4(0.0);
    v_id = a_id;
    return;
  }
  vec4 colour = a_colour;
  float size = a_size;
  if (u_element_colours) {
    colour = u_base_colour;
    size = u_base_size;
    if (a_id == u_selected) {
      colour = u_selected_colour;
      size = u_highlight_size + 2.0;
    } else if (a_id == u_hovered) {
      colour = u_hovered_colour;
      size = u_highlight_size;
    } else if (buffer_fetch(u_changed, int(a_id)).r != 0u) {
      colour = u_changed_colour;
      size = u_highlight_size;
    }
  }
  if (u_pick_size > 0.0) size = u_pick_size;
  v_colour = colour;
  v_id = a_id;
  gl_PointSize = size;
  vec4 view = u_view * vec4(a_position, 1.0);
  float distance = length(view.xyz);
  float pull = min(0.5 * size * u_pixel_scale * max(-view.z, 0.0), 0.5 * distance);
  if (distance > 0.0) view.xyz *= 1.0 - pull / distance;
  gl_Position = u_projection * view;
}
