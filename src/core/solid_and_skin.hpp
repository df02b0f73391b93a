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

template <class Traits, class In_solid>
void collect_skin(const typename Traits::Triangulation& triangulation, In_solid&& in_solid,
                  Reconstruction<Traits::dimension>& result) {
  constexpr int D = Traits::dimension;
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!in_solid(cell)) continue;
    for (int i = 0; i <= D; ++i) {
      const auto neighbour = cell->neighbor(i);
      if (!triangulation.is_infinite(neighbour) && in_solid(neighbour)) continue;
      Facet<D> facet;
      for (int j = 0; j < D; ++j) facet[j] = cell->vertex(Traits::facet_vertex[i][j])->info();
      result.surface.push_back(facet);
    }
  }
}

}  // namespace sculpt
