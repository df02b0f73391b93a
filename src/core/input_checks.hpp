// SPDX-License-Identifier: GPL-3.0-or-later
// The conditions under which the sculpting algorithm is defined: enough points, all finite, no
// two alike (found by the triangulation, named by refuse_duplicates), and not all on a line (2D)
// or plane (3D). Each failure is an Input_error with a one-line message that names the offending
// point.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <sstream>
#include <vector>

#include "point_names.hpp"

namespace sculpt {

// The dimension of the smallest affine space holding the points: 0 for a single point, 1 for a
// line, 2 for a plane, 3 otherwise (exact predicates).
template <class Traits>
int affine_dimension(const std::vector<typename Traits::Cgal_point>& points) {
  using Cgal_point = typename Traits::Cgal_point;
  const auto& first = points.front();
  const auto distinct =
      std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) { return p != first; });
  if (distinct == points.end()) return 0;
  const auto off_line = std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) {
    return !CGAL::collinear(first, *distinct, p);
  });
  if (off_line == points.end()) return 1;
  if constexpr (Traits::dimension == 2) {
    return 2;
  } else {
    const auto off_plane = std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) {
      return !CGAL::coplanar(first, *distinct, *off_line, p);
    });
    return off_plane == points.end() ? 2 : 3;
  }
}

// Throws Duplicate_points naming the first repeated point (in the points' lexicographic order)
// and the point it repeats, if there is one.
template <int D>
void refuse_duplicates(const std::vector<Point<D>>& samples) {
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return samples[a] < samples[b] || (samples[a] == samples[b] && a < b);
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (samples[order[k]] == samples[order[k - 1]]) {
      throw Duplicate_points(ordinal_point(order[k]) + " duplicates " +
                             ordinal_point(order[k - 1]) + " " +
                             describe_point<D>(samples[order[k]]));
    }
  }
}

template <class Traits>
void check_input(const std::vector<Point<Traits::dimension>>& samples, const Options& options) {
  constexpr int D = Traits::dimension;
  // Beyond a million the box's corners swamp the samples' coordinates in the predicates.
  if (!(options.box_factor > 1.0) || !(options.box_factor <= 1e6)) {
    throw Input_error("the box factor must be greater than 1 and at most 1e6");
  }
  if (!(options.alpha >= 0) || !std::isfinite(options.alpha)) {
    throw Input_error("alpha must be a positive radius, or 0 to choose it");
  }
  if (samples.size() < static_cast<std::size_t>(D + 1)) {
    throw Input_error("a " + std::to_string(D) + "D reconstruction needs at least " +
                      std::to_string(D + 1) + " points, got " + std::to_string(samples.size()));
  }
  if (samples.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 4)) {
    throw Input_error("too many points: " + std::to_string(samples.size()));
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (double x : samples[i]) {
      if (!std::isfinite(x)) {
        throw Input_error(ordinal_point(i) +
                          " has a coordinate that is not finite: " + describe_point<D>(samples[i]));
      }
    }
  }

  // Repeated points are not looked for here: the triangulation finds them (a repeated point
  // adds no vertex) and refuse_duplicates names them. A sort of the points only for this was
  // 1% of a run.

  std::vector<typename Traits::Cgal_point> points;
  points.reserve(samples.size());
  for (const auto& p : samples) points.push_back(Traits::to_cgal(p));
  const int spanned = affine_dimension<Traits>(points);
  if (spanned == 0) {
    throw Input_error("all " + std::to_string(samples.size()) + " points are the same point " +
                      describe_point<D>(samples.front()) + ": there is nothing to reconstruct");
  }
  if (spanned < D) {
    throw Input_error(D == 2 ? "all points are collinear: there is no curve to reconstruct"
                             : "all points are coplanar: there is no surface to reconstruct "
                               "(a planar curve needs --dim 2)");
  }
}

}  // namespace sculpt
