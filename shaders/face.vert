// Mesh faces: one vertex per mesh vertex id (world space, no model matrix), with its area-weighted
// normal for Phong shading. The face each triangle belongs to is looked up by gl_PrimitiveID in the
// fragment shader, so vertices can be shared between faces.
// Without gl_PrimitiveID (GLSL ES) the triangles are drawn with no vertex arrays: vertices 3t, 3t + 1 and 3t + 2 are
// triangle t's corners, pulled from u_corners (three vertex ids per triangle), u_positions and u_normals, and
// v_triangle hands t to the fragment shader in gl_PrimitiveID's place (render/gpu_mesh.h).
#if MESHEDIT_HAS_PRIMITIVE_ID
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
#else
uniform usamplerBuffer u_corners;
uniform samplerBuffer u_positions;
uniform samplerBuffer u_normals;
flat out int v_triangle;
#endif

uniform mat4 u_view_projection;

out vec3 v_world;
out vec3 v_normal;

void main() {
#if MESHEDIT_HAS_PRIMITIVE_ID
  vec3 position = a_position;
  vec3 normal = a_normal;
#else
  int triangle = gl_VertexID / 3;
  int corner = int(buffer_fetch(u_corners, triangle)[gl_VertexID - 3 * triangle]);
  vec3 position = buffer_fetch(u_positions, corner).xyz;
  vec3 normal = buffer_fetch(u_normals, corner).xyz;
  v_triangle = triangle;
#endif
  v_world = position;
  v_normal = normal;
  gl_Position = u_view_projection * vec4(position, 1.0);
}
