// CGAL's Advancing Front Surface Reconstruction (Cohen-Steiner & Da, 2004), as a method beside
// the others: it grows a surface from a seed triangle of its own Delaunay triangulation,
// adding at each border edge the candidate triangle of smallest radius that keeps the surface an
// oriented 2-manifold, so it never makes a non-manifold edge but may leave holes. It builds its
// triangulation itself (CGAL gives no way to hand it ours); stages 1 and 2 are still computed,
// so that the viewer shows the same Delaunay triangulation for every method.
#pragma once

#include <CGAL/Advancing_front_surface_reconstruction.h>

#include <array>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/stage_clock.hpp"
#include "outward_orientation.hpp"

namespace sculpt {

template <class Traits>
void run_advancing_front_method(Reconstruction<3>& result, Stage_clock& clock) {
  clock.start("advancing-front");
  const int n = static_cast<int>(result.sample_count());
  std::vector<typename Traits::Cgal_point> points;
  points.reserve(n);
  for (int s = 0; s < n; ++s) points.push_back(Traits::to_cgal(result.sites[s]));
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                               std::back_inserter(triangles));
  result.surface.reserve(triangles.size());
  for (const auto& t : triangles) {
    result.surface.push_back(
        {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  }
  orient_outward(result.sites, result.surface);
}

}  // namespace sculpt
