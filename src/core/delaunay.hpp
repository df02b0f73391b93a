// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 1: DT(S ∪ BBV), the Delaunay triangulation of the samples and the 2^D corners of the
// box BB, the samples' bounding box scaled about its centre by the box factor. The corners make
// every sample's Voronoi cell bounded, so every sample has two finite poles (section 3).
#pragma once

#include <CGAL/spatial_sort.h>

#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "stage_clock.hpp"

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
  std::vector<typename Traits::Cell_handle> infinite;
  Traits::incident_cells(triangulation, triangulation.infinite_vertex(), infinite);
  for (auto cell : infinite) cell->info() = -1;
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

// Inserts the sites from `first` on into the triangulation, each vertex knowing its site index,
// in CGAL's spatial order (a Hilbert sort of random batches), each located from the one inserted
// before: what CGAL's own range insertion does, here in steps so that the stage's progress is
// known. The points are sorted together with their indices, not the indices alone, so that the
// insertion reads them in order (bunny00 subdivided, the stage: 0.57 -> 0.55 s; the insertion
// alone now takes CGAL's own range insertion's time).
// The order is the same either way: the sort compares the same points in the same positions.
// The triangulation may be of another type than the method's first: the crusts' (the samples
// with the Voronoi vertices, or with the poles). A repeated point is one vertex, knowing the
// index of its last copy in the sorted order, as with CGAL's range insertion.
template <class Traits, class Triangulation = typename Traits::Triangulation>
void insert_in_spatial_order(Triangulation& triangulation,
                             const std::vector<Point<Traits::dimension>>& sites, std::size_t first,
                             const Stage_clock& clock) {
  std::vector<std::pair<typename Traits::Cgal_point, int>> sorted;
  sorted.reserve(sites.size() - first);
  for (std::size_t i = first; i < sites.size(); ++i) {
    sorted.emplace_back(Traits::to_cgal(sites[i]), static_cast<int>(i));
  }
  CGAL::spatial_sort(sorted.begin(), sorted.end(), typename Traits::Spatial_sort_traits());
  typename Triangulation::Vertex_handle hint;
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    clock.report_every(k, sorted.size(), 16384);
    hint = Traits::insert_near(triangulation, sorted[k].first, hint);
    hint->info() = sorted[k].second;
  }
}

// The sites S ∪ BBV: the samples, then the box's corners.
template <int D>
void gather_sites(std::vector<Point<D>> samples, const Options& options,
                  Reconstruction<D>& result) {
  const auto corners = box_corners<D>(samples, options.box_factor);
  result.sites = std::move(samples);
  result.sites.insert(result.sites.end(), corners.begin(), corners.end());
}

template <class Traits>
void build_delaunay(std::vector<Point<Traits::dimension>> samples, const Options& options,
                    typename Traits::Triangulation& triangulation,
                    Reconstruction<Traits::dimension>& result, const Stage_clock& clock) {
  gather_sites<Traits::dimension>(std::move(samples), options, result);
  insert_in_spatial_order<Traits>(triangulation, result.sites, 0, clock);
  number_cells<Traits>(triangulation, options.keep_triangulations, result.delaunay);
}

}  // namespace sculpt
