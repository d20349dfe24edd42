#version 330 core
// Mesh faces: one vertex per mesh vertex id (world space, no model matrix), with its area-weighted
// normal for Phong shading. The face each triangle belongs to is looked up by gl_PrimitiveID in the
// fragment shader, so vertices can be shared between faces.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view_projection;

out vec3 v_world;
out vec3 v_normal;

void main() {
  v_world = a_position;
  v_normal = a_normal;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
