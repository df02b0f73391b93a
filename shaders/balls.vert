#version 330 core
layout(location = 0) in vec3 center;
layout(location = 2) in float radius;
uniform mat4 view;
out vec3 view_center;
out float ball_radius;
void main() {
  view_center = (view * vec4(center, 1.0)).xyz;
  ball_radius = radius;
}
