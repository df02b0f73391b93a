// Stages 6-8 of the paper's method for a closed surface, without building DT(S ∪ OUP).
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

namespace sculpt {

// Per finite cell of DT(S ∪ BBV): 1 if it is in the sculpted solid.
template <class Traits>
std::vector<std::uint8_t> solid_cells_by_queries(
    const typename Traits::Triangulation& triangulation,
    const Reconstruction<Traits::dimension>& result, const Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  std::vector<Point<D>> inserted;
  inserted.reserve(result.insertion.inserted_poles.size());
  for (int pole : result.insertion.inserted_poles)
    inserted.push_back(result.poles.poles[pole].center);
  const Circumball_query<Traits> query(triangulation, inserted, true);

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

// The solid's cells and its skin, each facet facing away from the solid.
template <class Traits>
void solid_and_skin(const typename Traits::Triangulation& triangulation,
                    const std::vector<std::uint8_t>& solid,
                    Reconstruction<Traits::dimension>& result, Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  const auto in_solid = [&](typename Traits::Cell_handle cell) {
    return !triangulation.is_infinite(cell) && solid[cell->info()];
  };
  clock.start("solid");
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!solid[cell->info()]) continue;
    ++result.stats.solid_cells;
    if (!result.options.keep_solid) continue;
    Cell<D> sites;
    for (int i = 0; i <= D; ++i) sites[i] = cell->vertex(i)->info();
    result.solid.push_back(sites);
  }
  clock.start("surface");
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!solid[cell->info()]) continue;
    for (int i = 0; i <= D; ++i) {
      if (in_solid(cell->neighbor(i))) continue;
      Facet<D> facet;
      for (int j = 0; j < D; ++j) facet[j] = cell->vertex(Traits::facet_vertex[i][j])->info();
      result.surface.push_back(facet);
    }
  }
}

}  // namespace sculpt
