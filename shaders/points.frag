// SPDX-License-Identifier: GPL-3.0-or-later
// Round points with a thin dark rim, so overlapping points stay apart. In 3D each is shaded as
// a small sphere lit from the upper left of the viewer, so points read as lying in depth, and
// its depth follows the sphere's front, so nearer points cover farther ones roundly.
uniform vec4 color;
uniform int shaded;
uniform float depth_radius;  // the sphere's radius in window depth units (0: flat)
out vec4 fragment;
void main() {
  vec2 offset = (gl_PointCoord - vec2(0.5)) * 2.0;
  float r = length(offset);
  if (r > 1.0) discard;
  if (shaded == 0) {
    float rim = smoothstep(0.7, 0.95, r);
    fragment = vec4(mix(color.rgb, color.rgb * 0.45, rim), color.a);
    gl_FragDepth = gl_FragCoord.z;
    return;
  }
  // gl_PointCoord grows downwards: the normal's y is flipped.
  vec3 normal = vec3(offset.x, -offset.y, sqrt(max(0.0, 1.0 - r * r)));
  vec3 light = normalize(vec3(-0.4, 0.5, 0.8));
  float diffuse = max(dot(normal, light), 0.0);
  float highlight = pow(max(dot(reflect(-light, normal), vec3(0.0, 0.0, 1.0)), 0.0), 24.0);
  vec3 lit = color.rgb * (0.35 + 0.65 * diffuse) + vec3(0.35 * highlight);
  fragment = vec4(lit, color.a);
  gl_FragDepth = gl_FragCoord.z - depth_radius * normal.z;
}
