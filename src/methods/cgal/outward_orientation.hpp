// A consistently oriented closed surface bounds a positive volume when its normals point
// outward: the surfaces made by other libraries are turned that way, as ours are.
#pragma once

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

inline void orient_outward(const std::vector<Point<3>>& points, std::vector<Facet<3>>& surface) {
  double six_volume = 0;  // the sum of the signed volumes of the tetrahedra (origin, triangle)
  for (const auto& t : surface) {
    const auto &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    six_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  if (six_volume < 0) {
    for (auto& t : surface) std::swap(t[1], t[2]);
  }
}

}  // namespace sculpt
