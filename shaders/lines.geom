#version 330 core
// Thick lines: each segment becomes a quad of the given width in pixels. (glLineWidth > 1 is
// not available in a forward-compatible core context.)
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 viewport;
uniform float line_width;
void main() {
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
  // Keep both ends in front of the camera.
  if (a.w <= 0.0 || b.w <= 0.0) return;
  vec2 sa = a.xy / a.w * viewport, sb = b.xy / b.w * viewport;
  vec2 direction = sb - sa;
  if (length(direction) < 1e-6) direction = vec2(1.0, 0.0);
  vec2 normal = normalize(vec2(-direction.y, direction.x)) * line_width / viewport;
  gl_Position = vec4(a.xy + normal * a.w, a.zw); EmitVertex();
  gl_Position = vec4(a.xy - normal * a.w, a.zw); EmitVertex();
  gl_Position = vec4(b.xy + normal * b.w, b.zw); EmitVertex();
  gl_Position = vec4(b.xy - normal * b.w, b.zw); EmitVertex();
  EndPrimitive();
}
