#version 330 core
// Id pass for faces: the face's pick id (kind bits | face slot) into the R32UI target.
uniform usamplerBuffer u_triangle_faces;
uniform uint u_kind_bits;

out uint o_id;

void main() {
  o_id = u_kind_bits | texelFetch(u_triangle_faces, gl_PrimitiveID).r;
}
