// SPDX-License-Identifier: GPL-3.0-or-later
// Thick lines (glLineWidth > 1 exists neither in a forward-compatible core context nor in
// WebGL): each segment is one instance of a four-vertex strip, its quad widened to line_width
// pixels across the segment's direction on screen.
layout(location = 0) in vec3 start;
layout(location = 3) in vec3 end;
uniform mat4 view_projection;
uniform vec2 viewport;
uniform float line_width;
void main() {
  vec4 a = view_projection * vec4(start, 1.0), b = view_projection * vec4(end, 1.0);
  // Keep both ends in front of the camera: a segment reaching behind it is left out (the four
  // corners at one point outside the view make no triangle).
  if (a.w <= 0.0 || b.w <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec2 direction = b.xy / b.w * viewport - a.xy / a.w * viewport;
  if (length(direction) < 1e-6) direction = vec2(1.0, 0.0);
  vec2 across = normalize(vec2(-direction.y, direction.x)) * line_width / viewport;
  // Corners 0, 1 at the start, 2, 3 at the end; even on one side, odd on the other.
  vec4 end_point = gl_VertexID < 2 ? a : b;
  float side = gl_VertexID % 2 == 0 ? 1.0 : -1.0;
  gl_Position = vec4(end_point.xy + side * across * end_point.w, end_point.zw);
}
