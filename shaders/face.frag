// Mesh faces (one triangle slot per face, see render/slot_geometry.h), shaded flat (the face's Newell normal) or Phong (interpolated area-weighted vertex
// normals, plus a highlight). Back sides get their own colour so an inside-out face shows. Hovered,
// selected and changed faces are tinted: hovered and selected by id (uniforms), changed by a flag per
// face (a buffer texture), so a selection change never touches the big buffers.
in vec3 v_world;
in vec3 v_normal;
#if MESHEDIT_HAS_PRIMITIVE_ID
#define primitive_id gl_PrimitiveID
#else
flat in int v_triangle;  // face.vert: the triangle's number where GLSL has no gl_PrimitiveID
#define primitive_id v_triangle
#endif

uniform bool u_extra;                     // false: gl_PrimitiveID is the face slot (the first triangle of each face)
uniform usamplerBuffer u_extra_faces;     // true: the face slot of each later fan triangle of a polygon
uniform samplerBuffer u_face_normals;     // unit face normal by face slot (zero if degenerate)
uniform usamplerBuffer u_changed;         // 1 for faces the last operation changed, by face slot
uniform uint u_selected;                  // face slot, or 0xFFFFFFFF
uniform uint u_hovered;
uniform bool u_smooth;
uniform vec3 u_eye;
uniform vec3 u_light;  // unit direction towards the light
uniform vec4 u_face_colour;
uniform vec4 u_back_colour;
uniform vec4 u_selected_colour;
uniform vec4 u_hovered_colour;
uniform vec4 u_changed_colour;

out vec4 o_colour;

void main() {
  uint face = u_extra ? buffer_fetch(u_extra_faces, primitive_id).r : uint(primitive_id);
  vec3 n = buffer_fetch(u_face_normals, int(face)).xyz;
  if (dot(n, n) < 0.25) {
    // A degenerate face has no normal of its own: use the triangle's, turned to its front side.
    vec3 facing = cross(dFdx(v_world), dFdy(v_world));
    n = dot(facing, facing) > 0.0 ? normalize(facing) : vec3(0.0, 0.0, 1.0);
    if (!gl_FrontFacing) n = -n;
  }
  if (u_smooth && dot(v_normal, v_normal) > 1e-12) n = normalize(v_normal);

  vec4 base = u_face_colour;
  if (!gl_FrontFacing) {
    n = -n;
    base = u_back_colour;
  }
  if (face == u_selected) {
    base = mix(base, u_selected_colour, 0.8);
  } else if (face == u_hovered) {
    base = mix(base, u_hovered_colour, 0.6);
  } else if (buffer_fetch(u_changed, int(face)).r != 0u) {
    base = mix(base, u_changed_colour, 0.7);
  }

  vec3 view = normalize(u_eye - v_world);
  float diffuse = max(dot(n, u_light), 0.0);
  vec3 colour = base.rgb * (0.28 + 0.72 * diffuse);
  if (u_smooth) {
    vec3 half_vector = normalize(u_light + view);
    colour += vec3(0.3) * pow(max(dot(n, half_vector), 0.0), 40.0) * step(0.0, dot(n, u_light));
  }
  o_colour = vec4(colour, 1.0);
}
