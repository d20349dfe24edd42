// Round points with a dark rim, so a white vertex still shows on a light face.
flat in vec4 v_colour;

out vec4 o_colour;

void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  float r2 = dot(d, d);
  if (r2 > 1.0) discard;
  o_colour = vec4(r2 > 0.7 ? v_colour.rgb * 0.3 : v_colour.rgb, v_colour.a);
}
