// Id pass for faces: the face's pick id (kind bits | face slot) into the R32UI target. The first triangle of each
// face is drawn at its face slot (gl_PrimitiveID is the slot); the later triangles of polygons come in a second
// draw (u_extra) and name their face in u_extra_faces.
uniform bool u_extra;
uniform usamplerBuffer u_extra_faces;
uniform uint u_kind_bits;

#if MESHEDIT_HAS_PRIMITIVE_ID
#define primitive_id gl_PrimitiveID
#else
flat in int v_triangle;  // face.vert: the triangle's number where GLSL has no gl_PrimitiveID
#define primitive_id v_triangle
#endif

out uint o_id;

void main() {
  uint face = u_extra ? buffer_fetch(u_extra_faces, primitive_id).r : uint(primitive_id);
  o_id = u_kind_bits | face;
}
