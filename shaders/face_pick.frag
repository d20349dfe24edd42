#version 330 core
// Id pass for faces: the face's pick id (kind bits | face slot) into the R32UI target. The first triangle of each
// face is drawn at its face slot (gl_PrimitiveID is the slot); the later triangles of polygons come in a second
// draw (u_extra) and name their face in u_extra_faces.
uniform bool u_extra;
uniform usamplerBuffer u_extra_faces;
uniform uint u_kind_bits;

out uint o_id;

void main() {
  uint face = u_extra ? texelFetch(u_extra_faces, gl_PrimitiveID).r : uint(gl_PrimitiveID);
  o_id = u_kind_bits | face;
}
