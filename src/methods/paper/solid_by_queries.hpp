// SPDX-License-Identifier: GPL-3.0-or-later
// Stages 6-7 of the paper's method for a closed surface, without building DT(S ∪ OUP); the
// surface (stage 8) is then the solid's skin (core/solid_and_skin.hpp).
//
// The sculpted solid is the all-sample cells of DT(S ∪ OUP) (section 3.2); they are exactly the
// all-sample cells of DT(S ∪ BBV) whose circumballs hold no outer concave pole
// (circumball_query.hpp), decided with the perturbation CGAL's insertion uses, so the solid is
// the one insertion gives, cell for cell. Its skin, the surface of a closed reconstruction, is
// the facets between a solid cell and a cell that is not: in DT(S ∪ OUP) the cell across such a
// facet has a pole or box corner as apex, whether it was there before or made by an insertion.
// Inserting costs 0.7-2.2 triangulations on real inputs (huge conflict zones in the concavities
// and holes); one query per cell costs a fraction of one. The viewer, which shows DT(S ∪ OUP),
// and the bordered surfaces, whose rule reads apexes on both sides, still insert.
#pragma once

#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/circumball_query.hpp"
#include "../../core/stage_clock.hpp"
#include "pole_insertion.hpp"

namespace sculpt {

// Per finite cell of DT(S ∪ BBV): 1 if it is in the sculpted solid.
template <class Traits>
std::vector<std::uint8_t> solid_cells_by_queries(
    const typename Traits::Triangulation& triangulation,
    const Reconstruction<Traits::dimension>& result, const Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  const Point<D>* sites = result.sites.data();
  const Circumball_query<Traits> query(triangulation, sites + first_inserted_site(result),
                                       sites + result.sites.size(), true);

  const int n = static_cast<int>(result.sample_count());
  std::vector<std::uint8_t> solid(result.delaunay.cell_count, 0);
  std::size_t done = 0;
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (++done % 262144 == 0) clock.report(double(done) / double(result.delaunay.cell_count));
    bool all_samples = true;
    for (int i = 0; i <= D && all_samples; ++i) all_samples = cell->vertex(i)->info() < n;
    if (!all_samples) continue;
    const Point<D> center = Traits::from_cgal(Traits::circumcenter(triangulation, cell));
    solid[cell->info()] = !query.holds_point(cell, center);
  }
  return solid;
}

}  // namespace sculpt
