// SPDX-License-Identifier: GPL-3.0-or-later
// The few vector operations the extraction's geometry needs, on points of the samples.
#pragma once

#include <array>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt::extraction_detail {

using Vector = std::array<double, 3>;

inline Vector minus(const Point<3>& a, const Point<3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vector cross(const Vector& a, const Vector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// The normal of the triangle (a, b, c) of `points`, as long as twice its area.
inline Vector normal_of(const std::vector<Point<3>>& points, int a, int b, int c) {
  return cross(minus(points[b], points[a]), minus(points[c], points[a]));
}

}  // namespace sculpt::extraction_detail
