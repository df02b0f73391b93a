// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles lit by a headlight: flat shading from the screen-space derivatives of the position,
// or smooth from vertex normals. Both sides are lit, so a bordered sheet shows from behind.
in vec3 view_position;
in vec3 view_normal;
uniform vec4 color;
uniform bool lit;
uniform bool smooth_normals;
out vec4 fragment;
void main() {
  if (!lit) { fragment = color; return; }
  vec3 n = smooth_normals ? normalize(view_normal)
                          : normalize(cross(dFdx(view_position), dFdy(view_position)));
  vec3 to_eye = normalize(-view_position);
  float facing = abs(dot(n, to_eye));
  vec3 half_vector = normalize(to_eye + vec3(0.3, 0.5, 0.0));
  float specular = pow(abs(dot(n, half_vector)), 40.0) * 0.25;
  vec3 shade = color.rgb * (0.25 + 0.75 * facing) + vec3(specular);
  fragment = vec4(shade, color.a);
}
