// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's Advancing Front Surface Reconstruction (Cohen-Steiner & Da, 2004), as a method beside
// the others: it grows a surface from a seed triangle of its own Delaunay triangulation,
// adding at each border edge the candidate triangle of smallest radius that keeps the surface an
// oriented 2-manifold, so it never makes a non-manifold edge but may leave holes. It builds its
// triangulation itself (CGAL gives no way to hand it ours); stages 1 and 2 are computed only
// where triangulations are kept, so that the viewer shows the same Delaunay triangulation for
// every method (stage_plan.hpp).
//
// CGAL's Advancing Front breaks some ties by memory address: on noisy input its surface can
// change by a few triangles with the process's memory layout (measured on a noisy cap: 3 or 4
// samples left off under different malloc settings, the same build), so the viewer's surface
// and the command line's may differ there. Each is repeatable run to run.
#pragma once

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/canonical_order.hpp"
#include "../../core/stage_clock.hpp"
#include "outward_orientation.hpp"

namespace sculpt {

// CGAL's Advancing Front on the points, its triangles in the order it added them
// (advancing_front_growth.cpp).
std::vector<Facet<3>> advancing_front_in_order(const std::vector<Point<3>>& points);

// The call is the benchmark's yardstick's (src/yardsticks), on our normalised samples, with the
// order of the triangles kept for the stage `front`.
inline void run_advancing_front_method(Reconstruction<3>& result, Stage_clock& clock) {
  clock.start("advancing-front");
  const auto n = static_cast<std::ptrdiff_t>(result.sample_count());
  std::vector<Facet<3>> grown =
      advancing_front_in_order({result.sites.begin(), result.sites.begin() + n});
  orient_outward(result.sites, grown);
  // Canonical order for the surface (canonical_order.hpp); the growth order as indices into it.
  for (auto& triangle : grown) triangle = canonical_reading(triangle);
  std::vector<int> by_reading(grown.size());
  for (std::size_t i = 0; i < grown.size(); ++i) by_reading[i] = static_cast<int>(i);
  std::sort(by_reading.begin(), by_reading.end(),
            [&](int a, int b) { return grown[a] < grown[b]; });
  result.surface.clear();
  result.surface.reserve(grown.size());
  result.front.order.assign(grown.size(), 0);
  for (std::size_t place = 0; place < by_reading.size(); ++place) {
    result.surface.push_back(grown[by_reading[place]]);
    result.front.order[by_reading[place]] = static_cast<int>(place);
  }
}

}  // namespace sculpt
