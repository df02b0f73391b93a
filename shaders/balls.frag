// SPDX-License-Identifier: GPL-3.0-or-later
in vec2 local;
uniform vec4 color;
uniform bool translucent;
uniform float line_width;  // pixels, for outlines
out vec4 fragment;
void main() {
  float d = length(local);
  if (translucent) {
    if (d > 1.0) discard;
    float facing = sqrt(max(0.0, 1.0 - d * d));
    fragment = vec4(color.rgb * (0.35 + 0.65 * facing), color.a * 0.35);
    return;
  }
  // An outline line_width pixels wide, measured with the derivative of d.
  float pixel = max(fwidth(d), 1e-6);
  float distance_to_outline = abs(d - 1.0) / pixel;
  if (distance_to_outline > 0.5 * line_width + 0.5) discard;
  float coverage = clamp(0.5 * line_width + 0.5 - distance_to_outline, 0.0, 1.0);
  fragment = vec4(color.rgb, color.a * coverage);
}
