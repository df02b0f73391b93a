// The robust method's judgement of every all-sample cell of DT(S ∪ BBV): inner or outer, from the
// labelled poles alone. A cell is outer when
//   - its circumball holds an outer pole: inserting the outer poles, as the paper's sculpting
//     does (section 3.2), would destroy it; or
//   - its circumcentre lies in the power cell of an outer polar ball (the "power carve"): of the
//     polar balls of its own samples, the one of least power distance |x - c|² - r² is outer.
//     This is the power crust's inner/outer rule (Amenta, Choi, Kolluri 2001) applied to the
//     Delaunay cells; it removes cells that span undersampled parts, which no outer pole reaches.
//     The candidates are the poles of the cell's vertices, the balls that touch the cell: on
//     CGAL's knot1, fandisk, hand, femur, elephant, refined_elephant, bunny00 and armadillo this
//     gave the same surfaces as the nearest-power query over all poles, at a tenth of the cost.
// The cells themselves are not changed here; manifold_carving.hpp removes them.
#pragma once

#include <cstdint>
#include <limits>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/circumball_query.hpp"
#include "../../core/stage_clock.hpp"
#include "manifold_carving.hpp"

namespace sculpt {

template <int D>
std::vector<Point<D>> outer_pole_centers(const Reconstruction<D>& result) {
  std::vector<Point<D>> centers;
  for (std::size_t p = 0; p < result.poles.poles.size(); ++p) {
    if (result.propagation.labels[p] == Label::outer)
      centers.push_back(result.poles.poles[p].center);
  }
  return centers;
}

// The label of the polar ball of least power distance from x among the poles of `samples`.
template <int D, class Samples>
Label power_cell_label(const Reconstruction<D>& result, const Point<D>& x, const Samples& samples) {
  const auto& poles = result.poles;
  double least = std::numeric_limits<double>::infinity();
  Label label = Label::unlabelled;
  for (int s : samples) {
    for (int q : {poles.positive_pole[s], poles.negative_pole[s]}) {
      if (q < 0 || result.propagation.labels[q] == Label::unlabelled) continue;
      const Pole<D>& pole = poles.poles[q];
      double d2 = 0;
      for (int k = 0; k < D; ++k) d2 += (x[k] - pole.center[k]) * (x[k] - pole.center[k]);
      const double power = d2 - pole.radius * pole.radius;
      if (power < least) {
        least = power;
        label = result.propagation.labels[q];
      }
    }
  }
  return label;
}

template <class Traits>
Cell_judgement judge_cells(const typename Traits::Triangulation& triangulation,
                           const Reconstruction<Traits::dimension>& result,
                           const Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  // Strictly inside, decided exactly: the poles on the sphere (those of neighbouring cells can
  // be) do not destroy it.
  const Circumball_query<Traits> outer_poles(triangulation, outer_pole_centers(result), false);
  const int n = static_cast<int>(result.sample_count());
  Cell_judgement judgement;
  judgement.outer.assign(result.delaunay.cell_count, 0);
  judgement.radius2.assign(result.delaunay.cell_count, 0.0f);
  // Per cell, the samples that have it as an outer pole.
  judgement.outer_pole_of.assign(result.delaunay.cell_count, 0);
  for (std::size_t s = 0; s < result.sample_count(); ++s) {
    for (int q : {result.poles.positive_pole[s], result.poles.negative_pole[s]}) {
      if (q < 0 || result.propagation.labels[q] != Label::outer) continue;
      auto& count = judgement.outer_pole_of[result.poles.poles[q].cell];
      if (count < UINT16_MAX) ++count;
    }
  }
  std::size_t done = 0;
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (++done % 262144 == 0) clock.report(double(done) / double(result.delaunay.cell_count));
    std::array<int, D + 1> samples;
    bool all_samples = true;
    for (int i = 0; i <= D; ++i) {
      samples[i] = cell->vertex(i)->info();
      all_samples = all_samples && samples[i] < n;
    }
    if (!all_samples) continue;
    const Point<D> x = Traits::from_cgal(Traits::circumcenter(triangulation, cell));
    const Point<D>& corner = result.sites[samples[0]];
    double r2 = 0;
    for (int k = 0; k < D; ++k) r2 += (x[k] - corner[k]) * (x[k] - corner[k]);
    judgement.radius2[cell->info()] = static_cast<float>(r2);
    if (outer_poles.holds_point(cell, x)) {
      judgement.outer[cell->info()] = 1 + static_cast<int>(Carve_reason::outer_pole_inside);
    } else if (power_cell_label<D>(result, x, samples) == Label::outer) {
      judgement.outer[cell->info()] = 1 + static_cast<int>(Carve_reason::outer_power_cell);
    }
  }
  return judgement;
}

}  // namespace sculpt
