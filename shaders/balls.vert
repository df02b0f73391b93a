// SPDX-License-Identifier: GPL-3.0-or-later
// A ball is drawn as a square facing the camera, one instance of a four-vertex strip per ball;
// the fragment shader cuts out the circle (2D) or shades the sphere (3D).
layout(location = 0) in vec3 center;
layout(location = 2) in float radius;
uniform mat4 view;
uniform mat4 projection;
out vec2 local;  // position on the square, the ball's outline at length 1
void main() {
  vec2 corner = vec2(gl_VertexID % 2 == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  local = corner * 1.02;
  vec3 view_center = (view * vec4(center, 1.0)).xyz;
  gl_Position = projection * vec4(view_center + vec3(local * radius, 0.0), 1.0);
}
