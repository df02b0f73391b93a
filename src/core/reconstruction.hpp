// The sculpting algorithm, written once for every dimension: Traits is Traits_2 or Traits_3.
// Each stage is a function of its own file; this driver runs them in the paper's order, times
// them, and gathers the statistics.
#pragma once

#include <vector>

#include "delaunay.hpp"
#include "facet_topology.hpp"
#include "input_checks.hpp"
#include "pole_insertion.hpp"
#include "pole_separation.hpp"
#include "poles.hpp"
#include "sculpting.hpp"
#include "stage_clock.hpp"

namespace sculpt {

template <int D>
void count_labels(Reconstruction<D>& result) {
  Statistics& stats = result.stats;
  stats.poles = result.poles.poles.size();
  stats.convex_poles = result.seeds.convex_poles.size();
  for (Label label : result.propagation.labels) {
    stats.inner_poles += label == Label::inner;
    stats.outer_poles += label == Label::outer;
  }
  stats.unlabelled_poles = result.propagation.unlabelled;
  stats.conflicts = result.propagation.conflicts.size();
}

template <class Traits>
Reconstruction<Traits::dimension> reconstruct_with(
    const std::vector<Point<Traits::dimension>>& samples, const Options& options) {
  Reconstruction<Traits::dimension> result;
  result.options = options;
  result.stats.dimension = Traits::dimension;
  result.stats.samples = samples.size();
  Stage_clock clock(result.stats, result.options);

  clock.start("checks");
  check_input<Traits>(samples, options);

  typename Traits::Triangulation triangulation;
  clock.start("delaunay");
  build_delaunay<Traits>(samples, options, triangulation, result);
  result.stats.delaunay_cells = result.delaunay.cell_count;

  clock.start("poles");
  find_poles<Traits>(triangulation, result);

  clock.start("seeds");
  select_seeds(result);

  clock.start("propagation");
  propagate_labels(result, clock);
  count_labels(result);

  clock.start("insertion");
  choose_inserted_poles(result);
  insert_poles<Traits>(triangulation, result);
  result.stats.inserted_poles = result.insertion.inserted_poles.size();
  result.stats.sculpted_cells = result.sculpted_delaunay.cell_count;

  clock.start("solid");
  sculpt_solid<Traits>(triangulation, result);
  result.stats.solid_cells = result.solid.size();

  clock.start("surface");
  extract_surface<Traits>(triangulation, result);

  clock.start("topology");
  measure_topology<Traits::dimension>(samples.size(), result.surface, result.stats);
  clock.stop();
  return result;
}

}  // namespace sculpt
