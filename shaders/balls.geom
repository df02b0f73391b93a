#version 330 core
// A ball is drawn as a square facing the camera; the fragment shader cuts out the circle (2D)
// or shades the sphere (3D).
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 view_center[];
in float ball_radius[];
uniform mat4 projection;
out vec2 local;  // position on the square, the ball's outline at length 1
void main() {
  vec3 c = view_center[0];
  float r = ball_radius[0];
  vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));
  for (int i = 0; i < 4; ++i) {
    local = corners[i] * 1.02;
    gl_Position = projection * vec4(c + vec3(local * r, 0.0), 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
