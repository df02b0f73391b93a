// SPDX-License-Identifier: GPL-3.0-or-later
// Alpha shapes (Edelsbrunner & Mücke, 1994) through CGAL: the Delaunay cells whose circumball is
// smaller than a ball of radius alpha make a solid, and its boundary is the surface. One alpha
// serves the whole shape, so where the sampling is coarser than alpha the solid has holes, and
// where alpha is larger than a thin part or a cavity, it fills them. Unless the user gives alpha,
// we take the smallest whose solid is one piece holding every sample (CGAL's
// find_optimal_alpha(1), computed as optimal_alpha.hpp does), in REGULARIZED mode (no dangling
// faces). CGAL's alpha shape needs a triangulation of its own kind, of the samples alone; the
// shared stages 1-2 are built only where the viewer keeps them (stage_plan.hpp).
#pragma once

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/canonical_order.hpp"
#include "../../core/stage_clock.hpp"
#include "optimal_alpha.hpp"
#include "outward_orientation.hpp"

namespace sculpt {

// The stage `alpha`: every finite cell with its circumradius, smallest first (ties in canonical
// order), so that the first k cells are the alpha shape's solid at the k-th radius. Sorted on
// CGAL's own squared alpha, which decides the solid: the radius, a square root scaled back, can
// round two different alphas to one number.
template <class Alpha_shape>
void keep_filtration(const Alpha_shape& shape, int scale, Alpha_stage& stage) {
  std::vector<std::pair<double, Cell<3>>> cells;  // squared alpha, corners
  for (auto cell : shape.finite_cell_handles()) {
    const Cell<3> corners{cell->vertex(0)->info(), cell->vertex(1)->info(), cell->vertex(2)->info(),
                          cell->vertex(3)->info()};
    cells.push_back({CGAL::to_double(cell->get_alpha()), canonical_reading(corners)});
    if (!(shape.get_alpha() < cell->get_alpha())) ++stage.chosen;
  }
  std::sort(cells.begin(), cells.end());
  stage.cells.reserve(cells.size());
  stage.radii.reserve(cells.size());
  for (const auto& [squared_alpha, corners] : cells) {
    stage.cells.push_back(corners);
    stage.radii.push_back(std::ldexp(std::sqrt(squared_alpha), -scale));
  }
}

template <class Traits>
void run_alpha_shape_method(Reconstruction<3>& result, Stage_clock& clock) {
  using Kernel = typename Traits::Kernel;
  using Info_base = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
  using Vertex_base = CGAL::Alpha_shape_vertex_base_3<Kernel, Info_base>;
  // Numbered cells, for the search of the optimal alpha.
  using Cell_base = CGAL::Alpha_shape_cell_base_3<
      Kernel, CGAL::Triangulation_cell_base_with_info_3<
                  int, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>;
  using Tds = CGAL::Triangulation_data_structure_3<Vertex_base, Cell_base>;
  using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
  using Alpha_shape = CGAL::Alpha_shape_3<Delaunay>;

  clock.start("alpha-shape");
  const int n = static_cast<int>(result.sample_count());
  std::vector<std::pair<typename Traits::Cgal_point, int>> sites;
  sites.reserve(n);
  for (int s = 0; s < n; ++s) sites.push_back({Traits::to_cgal(result.sites[s]), s});
  Delaunay triangulation(sites.begin(), sites.end());
  Alpha_shape shape(triangulation, 0, Alpha_shape::REGULARIZED);
  // CGAL's alpha is a squared radius; the sites are the input scaled by 2^scale_exponent.
  const int scale = result.stats.scale_exponent;
  if (result.options.alpha > 0) {
    const double radius = std::ldexp(result.options.alpha, scale);
    shape.set_alpha(radius * radius);
  } else {
    const auto optimal = optimal_alpha_index(shape, 1);
    if (!optimal) {
      clock.start("surface");  // as planned, and empty: no alpha gives one piece
      return;
    }
    shape.set_alpha(*(shape.alpha_begin() + static_cast<std::ptrdiff_t>(*optimal)));
  }
  result.stats.alpha = std::ldexp(std::sqrt(CGAL::to_double(shape.get_alpha())), -scale);

  clock.start("surface");
  for (auto cell : shape.finite_cell_handles()) {
    if (shape.classify(cell) != Alpha_shape::INTERIOR) continue;
    result.solid.push_back({cell->vertex(0)->info(), cell->vertex(1)->info(),
                            cell->vertex(2)->info(), cell->vertex(3)->info()});
  }
  result.stats.solid_cells = result.solid.size();
  for (auto facet = shape.finite_facets_begin(); facet != shape.finite_facets_end(); ++facet) {
    if (shape.classify(*facet) != Alpha_shape::REGULAR) continue;
    // Face away from the interior cell of the two.
    auto [cell, opposite] = *facet;
    if (shape.is_infinite(cell) || shape.classify(cell) != Alpha_shape::INTERIOR) {
      const auto mirror = shape.mirror_facet(*facet);
      cell = mirror.first;
      opposite = mirror.second;
    }
    Facet<3> triangle;
    for (int j = 0; j < 3; ++j) {
      triangle[j] = cell->vertex(Traits::facet_vertex[opposite][j])->info();
    }
    result.surface.push_back(triangle);
  }
  if (result.options.keep_triangulations) keep_filtration(shape, scale, result.alpha);
  put_in_canonical_order(result.surface);
  put_in_canonical_order(result.solid);
  if (!result.options.keep_solid) result.solid.clear();
}

}  // namespace sculpt
