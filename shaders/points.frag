#version 330 core
// Round points with a thin dark rim, so overlapping points stay apart.
uniform vec4 color;
out vec4 fragment;
void main() {
  float r = length(gl_PointCoord - vec2(0.5)) * 2.0;
  if (r > 1.0) discard;
  float rim = smoothstep(0.7, 0.95, r);
  fragment = vec4(mix(color.rgb, color.rgb * 0.45, rim), color.a);
}
