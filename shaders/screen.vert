// SPDX-License-Identifier: GPL-3.0-or-later
// Overlays (legend, title) in pixel coordinates, origin at the top left.
layout(location = 0) in vec3 position;
uniform vec2 viewport;
void main() {
  gl_Position = vec4(2.0 * position.x / viewport.x - 1.0, 1.0 - 2.0 * position.y / viewport.y, 0.0, 1.0);
}
