// The sculpting algorithm, written once for every dimension: Traits is Traits_2 or Traits_3.
// Each stage is a function of its own file; this driver runs them in the paper's order, times
// them, and gathers the statistics.
#pragma once

#include <algorithm>
#include <chrono>
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
  std::vector<bool> conflicted(result.poles.poles.size(), false);
  for (const auto& offer : result.propagation.conflicts) conflicted[offer.pole] = true;
  stats.conflicts =
      static_cast<std::size_t>(std::count(conflicted.begin(), conflicted.end(), true));
  stats.conflict_offers = result.propagation.conflicts.size();
}

// CGAL's Delaunay triangulation of the points alone, timed: the benchmark's yardstick.
template <class Traits>
double time_plain_delaunay(const std::vector<Point<Traits::dimension>>& points) {
  std::vector<typename Traits::Cgal_point> cgal_points;
  cgal_points.reserve(points.size());
  for (const auto& p : points) cgal_points.push_back(Traits::to_cgal(p));
  const auto start = std::chrono::steady_clock::now();
  typename Traits::Triangulation triangulation(cgal_points.begin(), cgal_points.end());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return triangulation.number_of_vertices() > 0 ? seconds : 0.0;
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
