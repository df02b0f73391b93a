// SPDX-License-Identifier: GPL-3.0-or-later
// Points with a size in pixels, whatever the zoom.
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
uniform float point_size;
void main() {
  gl_Position = view_projection * vec4(position, 1.0);
  gl_PointSize = point_size;
}
