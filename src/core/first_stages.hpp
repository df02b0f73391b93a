// Stages 1-2 (DT(S ∪ BBV) and the poles) handed from one attempt of a reconstruction to the
// next on the same samples: the automatic kind's bordered attempt follows a closed one
// (automatic_kind.hpp), and the robust method's bordered surface never reads the first
// triangulation itself (it builds DT(S ∪ BBV ∪ UP) anew from the sites, pole_insertion.hpp), only
// the sites, the cells' count (and the cells, where the viewer keeps them) and the poles. On
// noisy closed scans, where the bordered attempt runs and is dropped, the Delaunay triangulation
// and the poles were a fifth of it (a noisy torus of 20k points: 0.09 s of the attempt's 0.49).
#pragma once

#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "stage_plan.hpp"

namespace sculpt {

// What stages 1-2 leave, in the normalised coordinates the stages work in.
template <int D>
struct First_stages {
  std::vector<Point<D>> sites;  // the samples, then the box's corners
  Delaunay_stage<D> delaunay;
  Poles_stage<D> poles;
  std::size_t delaunay_cells = 0;
};

// What a finished run must leave for its first stages to be handed on: the coordinates its
// result gives back in the input's units (the rest of stages 1-2 is in the result as it was).
// Taken at the end of the run, not after stage 2, so that a run whose successor never comes
// (a closed scan: no bordered attempt) holds no copy while its own stages work.
template <int D>
struct Normalised_coordinates {
  std::vector<Point<D>> sites;
  std::vector<Point<D>> pole_centers;
  std::vector<double> pole_radii;
};

// Whether a run with these options can start from another attempt's first stages instead of
// building its own: it must not read the first triangulation (only the robust method's bordered
// surface in 3D, which rebuilds it with the poles; in 2D it joins neighbours along it).
inline bool starts_from_first_stages(const Options& options, int dimension) {
  return options.method == Method::robust && dimension == 3 &&
         inserts_poles(Method::robust, options.kind, dimension);
}

template <int D>
Normalised_coordinates<D> normalised_coordinates_of(const Reconstruction<D>& result) {
  Normalised_coordinates<D> kept;
  kept.sites = result.sites;
  kept.pole_centers.reserve(result.poles.poles.size());
  kept.pole_radii.reserve(result.poles.poles.size());
  for (const auto& pole : result.poles.poles) {
    kept.pole_centers.push_back(pole.center);
    kept.pole_radii.push_back(pole.radius);
  }
  return kept;
}

// A finished run's first stages, from its result and the coordinates it left.
template <int D>
First_stages<D> first_stages_of(const Reconstruction<D>& result,
                                Normalised_coordinates<D> coordinates) {
  First_stages<D> stages{std::move(coordinates.sites), result.delaunay, result.poles,
                         result.stats.delaunay_cells};
  for (std::size_t p = 0; p < stages.poles.poles.size(); ++p) {
    stages.poles.poles[p].center = coordinates.pole_centers[p];
    stages.poles.poles[p].radius = coordinates.pole_radii[p];
  }
  return stages;
}

template <int D>
void take_over(First_stages<D>&& stages, Reconstruction<D>& result) {
  result.sites = std::move(stages.sites);
  result.delaunay = std::move(stages.delaunay);
  result.poles = std::move(stages.poles);
  result.stats.delaunay_cells = stages.delaunay_cells;
  result.stats.poles = result.poles.poles.size();
}

}  // namespace sculpt
