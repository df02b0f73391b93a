// SPDX-License-Identifier: GPL-3.0-or-later
// Picking: which of some points lies nearest the mouse on screen, within a few pixels.
#pragma once

#include <glm/glm.hpp>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt::viewer {

// Index of the point whose projection is nearest `mouse` (pixels, origin top left) and closer
// than `radius` pixels, preferring the one nearest the camera among near ties; -1 if none.
template <int D>
int pick_nearest(const std::vector<Point<D>>& points, std::size_t count,
                 const glm::mat4& view_projection, glm::vec2 mouse, glm::vec2 viewport,
                 float radius = 10.0f) {
  int best = -1;
  float best_score = radius * radius;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec4 clip =
        view_projection * glm::vec4(float(points[i][0]), float(points[i][1]),
                                    D == 3 ? float(points[i][D - 1]) : 0.0f, 1.0f);
    if (clip.w <= 0) continue;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    const glm::vec2 screen((ndc.x + 1) * 0.5f * viewport.x, (1 - ndc.y) * 0.5f * viewport.y);
    const glm::vec2 offset = screen - mouse;
    const float score = glm::dot(offset, offset) + 4.0f * ndc.z;  // nearer the camera wins ties
    if (score < best_score) {
      best_score = score;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace sculpt::viewer
