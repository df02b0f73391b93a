// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a point lies inside a closed piece of surface: the ray from it crosses the piece an odd
// number of times. The walk (manifold_extraction.hpp) asks this of every piece it has walked,
// from the extreme sample of each new piece, to tell a cavity's wall from a second object. On a
// noisy scan that falls into thousands of small pieces, testing every triangle of the large
// piece for each of them cost a third of the whole run (a noisy sheet of 100k samples: 2.5 s).
// So the triangles are binned by their shadow on a plane across the ray: the ray's line meets a
// triangle only where the point's shadow lies in the triangle's, so a query tests only the
// triangles whose shadow's box (widened against rounding) holds the point's. Same test, same
// answer, a few triangles per query.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "vector3.hpp"

namespace sculpt {

// A direction for the rays, in no plane of the coordinate axes, so that a ray from a sample
// rarely passes exactly through another sample or along an edge (which a ray towards +x does at
// once on inputs sampled on a grid).
inline constexpr std::array<double, 3> ray_direction{1.0, 0.3183098861837907, 0.2236067977499790};

// Whether the ray from p along ray_direction crosses the triangle (Möller & Trumbore).
inline bool ray_crosses(const std::vector<Point<3>>& points, const Facet<3>& t, const Point<3>& p) {
  using extraction_detail::cross;
  using extraction_detail::dot;
  using extraction_detail::minus;
  const auto& d = ray_direction;
  const Point<3>& a = points[t[0]];
  const auto e1 = minus(points[t[1]], a), e2 = minus(points[t[2]], a);
  const auto h = cross(d, e2);
  const double det = dot(e1, h);
  if (det == 0) return false;  // the ray runs parallel to the triangle
  const auto from_a = minus(p, a);
  const double u = dot(from_a, h) / det;
  if (u < 0 || u > 1) return false;
  const auto q = cross(from_a, e1);
  const double v = dot(d, q) / det;
  if (v < 0 || u + v > 1) return false;
  return dot(e2, q) / det > 0;
}

class Ray_crossings {
 public:
  // The triangles [first, last) of `triangles`, which must outlive this.
  Ray_crossings(const std::vector<Point<3>>& points, const std::vector<Facet<3>>& triangles,
                std::size_t first, std::size_t last)
      : points_(points), triangles_(triangles) {
    const std::size_t count = last - first;
    std::vector<std::array<double, 4>> boxes(count);  // shadow boxes: lo s, lo t, hi s, hi t
    for (std::size_t i = 0; i < count; ++i) {
      auto& box = boxes[i];
      box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (int v : triangles[first + i]) {
        const auto [s, t] = shadow(points[v]);
        box = {std::min(box[0], s), std::min(box[1], t), std::max(box[2], s), std::max(box[3], t)};
      }
      for (int k = 0; k < 2; ++k) {
        lower_[k] = std::min(lower_[k], box[k]);
        upper_[k] = std::max(upper_[k], box[k + 2]);
      }
    }
    if (count == 0) return;
    // Widened by a relative 1e-9: the crossing test, computed another way, may accept a point
    // a rounding error outside the triangle's shadow.
    const double widen =
        1e-9 * std::max({upper_[0] - lower_[0], upper_[1] - lower_[1], std::abs(lower_[0]),
                         std::abs(upper_[0]), std::abs(lower_[1]), std::abs(upper_[1]), 1e-300});
    for (int k = 0; k < 2; ++k) lower_[k] -= widen, upper_[k] += widen;
    side_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(count) / 2)));
    std::vector<int> filled(std::size_t(side_) * side_ + 1, 0);
    const auto cells_of = [&](const std::array<double, 4>& box, auto&& visit) {
      const int s0 = cell(box[0] - widen, 0), s1 = cell(box[2] + widen, 0);
      const int t0 = cell(box[1] - widen, 1), t1 = cell(box[3] + widen, 1);
      for (int t = t0; t <= t1; ++t) {
        for (int s = s0; s <= s1; ++s) visit(t * side_ + s);
      }
    };
    for (const auto& box : boxes) cells_of(box, [&](int c) { ++filled[c + 1]; });
    for (std::size_t c = 1; c < filled.size(); ++c) filled[c] += filled[c - 1];
    start_ = filled;
    in_cells_.resize(filled.back());
    for (std::size_t i = 0; i < count; ++i) {
      cells_of(boxes[i], [&](int c) { in_cells_[filled[c]++] = static_cast<int>(first + i); });
    }
  }

  // Whether the ray from p crosses the triangles an odd number of times.
  bool odd_from(const Point<3>& p) const {
    const auto [s, t] = shadow(p);
    if (side_ == 0 || s < lower_[0] || s > upper_[0] || t < lower_[1] || t > upper_[1]) {
      return false;
    }
    const int c = cell(t, 1) * side_ + cell(s, 0);
    bool odd = false;
    for (int i = start_[c]; i < start_[c + 1]; ++i) {
      odd ^= ray_crosses(points_, triangles_[in_cells_[i]], p);
    }
    return odd;
  }

 private:
  // Coordinates on a plane across the ray: along two directions perpendicular to it.
  static std::array<double, 2> shadow(const Point<3>& p) {
    const auto& d = ray_direction;
    // across = d x (0, 0, 1), up = d x across (not normalised: only their directions matter).
    const extraction_detail::Vector across = {d[1], -d[0], 0};
    const extraction_detail::Vector up = extraction_detail::cross(d, across);
    const extraction_detail::Vector at = {p[0], p[1], p[2]};
    return {extraction_detail::dot(at, across), extraction_detail::dot(at, up)};
  }

  int cell(double x, int axis) const {
    const double extent = upper_[axis] - lower_[axis];
    const int c = extent > 0 ? static_cast<int>((x - lower_[axis]) / extent * side_) : 0;
    return std::clamp(c, 0, side_ - 1);
  }

  const std::vector<Point<3>>& points_;
  const std::vector<Facet<3>>& triangles_;
  std::array<double, 2> lower_ = {INFINITY, INFINITY}, upper_ = {-INFINITY, -INFINITY};
  int side_ = 0;
  std::vector<int> start_, in_cells_;
};

}  // namespace sculpt
