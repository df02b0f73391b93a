// SPDX-License-Identifier: GPL-3.0-or-later
#include "../core/jet_smoothing.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_smooth_point_set.h>

namespace sculpt {

std::vector<Point<3>> jet_smoothed(const std::vector<Point<3>>& samples, unsigned neighbours) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> points;
  points.reserve(samples.size());
  for (const auto& p : samples) points.emplace_back(p[0], p[1], p[2]);
  CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(points, neighbours);
  std::vector<Point<3>> smoothed;
  smoothed.reserve(points.size());
  for (const auto& p : points) smoothed.push_back({p.x(), p.y(), p.z()});
  return smoothed;
}

}  // namespace sculpt
