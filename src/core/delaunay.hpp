// Stage 1: DT(S ∪ BBV), the Delaunay triangulation of the samples and the 2^D corners of the
// box BB, the samples' bounding box scaled about its centre by the box factor. The corners make
// every sample's Voronoi cell bounded, so every sample has two finite poles (section 3).
#pragma once

#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

namespace sculpt {

template <int D>
std::vector<Point<D>> box_corners(const std::vector<Point<D>>& samples, double box_factor) {
  Point<D> lo = samples.front(), hi = samples.front();
  for (const auto& p : samples) {
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  std::vector<Point<D>> corners(1u << D);
  for (unsigned c = 0; c < corners.size(); ++c) {
    for (int k = 0; k < D; ++k) {
      const double center = 0.5 * (lo[k] + hi[k]);
      const double half_side = 0.5 * box_factor * (hi[k] - lo[k]);
      corners[c][k] = (c >> k) & 1u ? center + half_side : center - half_side;
    }
  }
  return corners;
}

// Gives every finite cell its index among the finite cells, and infinite cells -1; copies the
// cells into `stage` when the caller keeps triangulations.
template <class Traits>
void number_cells(typename Traits::Triangulation& triangulation, bool keep_cells,
                  Delaunay_stage<Traits::dimension>& stage) {
  for (auto cell : Traits::all_cells(triangulation)) cell->info() = -1;
  int next = 0;
  stage.cells.clear();
  for (auto cell : Traits::finite_cells(triangulation)) {
    cell->info() = next++;
    if (keep_cells) {
      Cell<Traits::dimension> sites;
      for (int i = 0; i <= Traits::dimension; ++i) sites[i] = cell->vertex(i)->info();
      stage.cells.push_back(sites);
    }
  }
  stage.cell_count = static_cast<std::size_t>(next);
}

template <class Traits>
void build_delaunay(const std::vector<Point<Traits::dimension>>& samples, const Options& options,
                    typename Traits::Triangulation& triangulation,
                    Reconstruction<Traits::dimension>& result) {
  result.sites = samples;
  for (const auto& corner : box_corners<Traits::dimension>(samples, options.box_factor)) {
    result.sites.push_back(corner);
  }
  std::vector<std::pair<typename Traits::Cgal_point, int>> sites;
  sites.reserve(result.sites.size());
  for (std::size_t i = 0; i < result.sites.size(); ++i) {
    sites.emplace_back(Traits::to_cgal(result.sites[i]), static_cast<int>(i));
  }
  triangulation.insert(sites.begin(), sites.end());  // spatially sorted by CGAL
  number_cells<Traits>(triangulation, options.keep_triangulations, result.delaunay);
}

}  // namespace sculpt
