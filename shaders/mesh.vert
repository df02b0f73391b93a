// SPDX-License-Identifier: GPL-3.0-or-later
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 view;
uniform mat4 view_projection;
out vec3 view_position;
out vec3 view_normal;
void main() {
  view_position = (view * vec4(position, 1.0)).xyz;
  view_normal = mat3(view) * normal;
  gl_Position = view_projection * vec4(position, 1.0);
}
