// SPDX-License-Identifier: GPL-3.0-or-later
// Stages 7 and 8 for a solid given as a set of cells of a triangulation (the all-sample cells of
// DT(S ∪ OUP), those that survive the circumball queries, those the robust carving leaves):
// the solid's cells, counted and kept when asked for (Options::keep_solid), and its skin, the
// facets between a solid cell and one that is not, facing away from the solid.
#pragma once

#include <sculpt/sculpt.hpp>

namespace sculpt {

// `in_solid(cell)` says whether a finite cell is in the solid.
template <class Traits, class In_solid>
void collect_solid(const typename Traits::Triangulation& triangulation, In_solid&& in_solid,
                   Reconstruction<Traits::dimension>& result) {
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!in_solid(cell)) continue;
    ++result.stats.solid_cells;
    if (!result.options.keep_solid) continue;
    Cell<Traits::dimension> sites;
    for (int i = 0; i <= Traits::dimension; ++i) sites[i] = cell->vertex(i)->info();
    result.solid.push_back(sites);
  }
}

// The facet of `cell` opposite its vertex i, its sites facing away from the cell.
template <class Traits>
Facet<Traits::dimension> facet_facing_out(typename Traits::Cell_handle cell, int i) {
  Facet<Traits::dimension> facet;
  for (int j = 0; j < Traits::dimension; ++j)
    facet[j] = cell->vertex(Traits::facet_vertex[i][j])->info();
  return facet;
}

template <class Traits, class In_solid>
void collect_skin(const typename Traits::Triangulation& triangulation, In_solid&& in_solid,
                  Reconstruction<Traits::dimension>& result) {
  constexpr int D = Traits::dimension;
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!in_solid(cell)) continue;
    for (int i = 0; i <= D; ++i) {
      const auto neighbour = cell->neighbor(i);
      if (!triangulation.is_infinite(neighbour) && in_solid(neighbour)) continue;
      result.surface.push_back(facet_facing_out<Traits>(cell, i));
    }
  }
}

}  // namespace sculpt
