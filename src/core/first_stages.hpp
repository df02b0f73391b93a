// SPDX-License-Identifier: GPL-3.0-or-later
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

namespace sculpt {

// What stages 1-2 leave beside the sites (which the samples give again, the same: delaunay.hpp's
// gather_sites), in the normalised coordinates the stages work in.
template <int D>
struct First_stages {
  Delaunay_stage<D> delaunay;
  Poles_stage<D> poles;
};

// What a finished run must leave for its first stages to be handed on: its poles' centres and
// radii as the stages computed them, which its result gives back in the input's units (the rest
// of stages 1-2 is in the result as it was). Taken at the end of the run, not after stage 2, so
// that a run whose successor never comes (a closed scan: no bordered attempt) holds no copy while
// its own stages work.
template <int D>
struct Normalised_poles {
  std::vector<Point<D>> centers;
  std::vector<double> radii;
};

// Whether a run with these options can start from another attempt's first stages instead of
// building its own: it must not read the first triangulation (only the robust method's bordered
// surface in 3D, which rebuilds it with the poles; in 2D it joins neighbours along it).
inline bool starts_from_first_stages(const Options& options, int dimension) {
  return options.method == Method::robust && dimension == 3 &&
         inserts_poles(Method::robust, options.kind, dimension);
}

template <int D>
Normalised_poles<D> normalised_poles_of(const Reconstruction<D>& result) {
  Normalised_poles<D> kept;
  kept.centers.reserve(result.poles.poles.size());
  kept.radii.reserve(result.poles.poles.size());
  for (const auto& pole : result.poles.poles) {
    kept.centers.push_back(pole.center);
    kept.radii.push_back(pole.radius);
  }
  return kept;
}

// A finished run's first stages, from its result and the poles it left (freed here).
template <int D>
First_stages<D> first_stages_of(const Reconstruction<D>& result, Normalised_poles<D> poles) {
  First_stages<D> stages{result.delaunay, result.poles};
  for (std::size_t p = 0; p < stages.poles.poles.size(); ++p) {
    stages.poles.poles[p].center = poles.centers[p];
    stages.poles.poles[p].radius = poles.radii[p];
  }
  return stages;
}

template <int D>
void take_over(First_stages<D>&& stages, Reconstruction<D>& result) {
  result.delaunay = std::move(stages.delaunay);
  result.poles = std::move(stages.poles);
  result.stats.delaunay_cells = result.delaunay.cell_count;
  result.stats.poles = result.poles.poles.size();
}

}  // namespace sculpt
