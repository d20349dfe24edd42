// Id pass for segments (edges, halfedge arrows) and points (vertices): kind bits | element index.
flat in uint v_id;
uniform uint u_kind_bits;

out uint o_id;

void main() {
  o_id = u_kind_bits | v_id;
}
