// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a cell around an edge of a 3D triangulation passes a test: the question both hull
// carvings (the robust one and Boissonnat's) ask of the edge opposite two facets of a cell that
// touch the outside, whose removal is a manifold only if no cell around that edge is outside.
#pragma once

namespace sculpt {

// The edge between vertices i and j of `cell`. In 2D an edge has no cells around it beyond its
// two faces, and the carvings do not ask: false.
template <class Traits, class Test>
bool any_cell_around_edge(const typename Traits::Triangulation& triangulation,
                          typename Traits::Cell_handle cell, int i, int j, Test&& test) {
  if constexpr (Traits::dimension == 3) {
    const auto first = triangulation.incident_cells(cell, i, j);
    auto around = first;
    do {
      if (test(around)) return true;
    } while (++around != first);
  }
  return false;
}

}  // namespace sculpt
