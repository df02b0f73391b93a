// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction, written once for every dimension: Traits is Traits_2 or Traits_3. Each
// stage is a function of its own file. This driver runs the stages every method shares (checks,
// Delaunay, poles), hands the triangulation to the chosen method (src/methods), then
// measures the result's topology; it times every stage and gathers the statistics.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "../core/closed_skin_check.hpp"
#include "../core/delaunay.hpp"
#include "../core/exact_normalisation.hpp"
#include "../core/facet_topology.hpp"
#include "../core/first_stages.hpp"
#include "../core/input_checks.hpp"
#include "../core/poles.hpp"
#include "../core/seeds.hpp"
#include "../core/stage_clock.hpp"
#include "../core/stage_plan.hpp"
#include "../core/thin_handles.hpp"
#include "../methods/boissonnat/boissonnat_method.hpp"
#include "../methods/cgal/advancing_front_method.hpp"
#include "../methods/cgal/alpha_shape_method.hpp"
#include "../methods/cocone/cocone_method.hpp"
#include "../methods/cocone/tight_cocone_method.hpp"
#include "../methods/crust/crust_method.hpp"
#include "../methods/crust/nn_crust.hpp"
#include "../methods/crust/surface_crust.hpp"
#include "../methods/paper/paper_method.hpp"
#include "../methods/power_crust/power_crust_method.hpp"
#include "../methods/robust/robust_method.hpp"

namespace sculpt {

// `keep`: where to leave the normalised poles of stages 1-2 for a later attempt on the same
// samples; `given`: an earlier attempt's stages 1-2, taken over (moved from) when this run does
// not read the first triangulation (first_stages.hpp).
template <class Traits>
Reconstruction<Traits::dimension> reconstruct_with(
    const std::vector<Point<Traits::dimension>>& samples, const Options& options,
    Normalised_poles<Traits::dimension>* keep = nullptr,
    First_stages<Traits::dimension>* given = nullptr) {
  Reconstruction<Traits::dimension> result;
  result.options = options;
  result.stats.dimension = Traits::dimension;
  result.stats.method = options.method;
  result.stats.kind = options.kind;
  result.stats.samples = samples.size();
  Stage_clock clock(result.stats, result.options);
  const bool reuses = given && starts_from_first_stages(options, Traits::dimension);
  clock.plan(planned_stages(options, Traits::dimension, reuses));

  clock.start("checks");
  if (!reconstructs_in(options.method, Traits::dimension)) {
    throw Input_error(std::string("the method ") + to_string(options.method) +
                      (Traits::dimension == 3
                           ? " reconstructs curves (2D points) only; for surfaces use robust, "
                             "paper, crust, cocone, tight-cocone, advancing-front, alpha-shape, "
                             "power-crust or boissonnat"
                           : " reconstructs surfaces (3D points) only; for curves use robust, "
                             "paper, crust, nn-crust, power-crust or boissonnat"));
  }
  check_input<Traits>(samples, options);
  const Normalisation<Traits::dimension> normalisation =
      normalisation_of<Traits::dimension>(samples);
  // Checked even when nothing moves: a coordinate too small against the others is refused.
  // The sites start as these (build_delaunay or gather_sites takes them over).
  std::vector<Point<Traits::dimension>> work =
      normalised<Traits::dimension>(samples, normalisation);
  result.stats.scale_exponent = normalisation.exponent;
  for (int k = 0; k < Traits::dimension; ++k) result.stats.translation[k] = normalisation.offset[k];

  typename Traits::Triangulation triangulation;
  if (reuses) {
    gather_sites<Traits::dimension>(std::move(work), options, result);  // as the attempt did
    take_over(std::move(*given), result);
  } else if (builds_shared_stages(options)) {
    clock.start("delaunay");
    build_delaunay<Traits>(std::move(work), options, triangulation, result, clock);
    if (triangulation.number_of_vertices() != result.sites.size()) {  // a site repeated
      refuse_duplicates<Traits::dimension>(samples);
      throw Input_error(
          "a corner of the box falls on a sample (rounding): choose a larger box factor");
    }
    result.stats.delaunay_cells = result.delaunay.cell_count;

    clock.start("poles");
    find_poles<Traits>(triangulation, result, clock);
    result.stats.poles = result.poles.poles.size();
  } else {
    refuse_duplicates<Traits::dimension>(samples);  // no triangulation of ours finds them
    gather_sites<Traits::dimension>(std::move(work), options, result);
  }

  // A method whose surface passed check_closed_skin hands the check on, not to make it twice.
  std::optional<Skin_check> checked_skin;
  switch (options.method) {
    case Method::paper:
      clock.start("seeds");
      select_seeds(result);
      run_paper_method<Traits>(triangulation, result, clock);
      break;
    case Method::robust:
      clock.start("seeds");
      select_seeds(result);
      checked_skin = run_robust_method<Traits>(triangulation, result, clock);
      break;
    case Method::crust:
      if constexpr (Traits::dimension == 2) {
        run_crust_method<Traits>(triangulation, result, clock);
      } else {
        run_surface_crust_method<Traits>(triangulation, result, clock);
      }
      break;
    case Method::nn_crust:
      if constexpr (Traits::dimension == 2) {
        run_nn_crust_method<Traits>(triangulation, result, clock);
      }
      break;
    case Method::cocone:
      if constexpr (Traits::dimension == 3) run_cocone_method<Traits>(triangulation, result, clock);
      break;
    case Method::advancing_front:
      if constexpr (Traits::dimension == 3) run_advancing_front_method(result, clock);
      break;
    case Method::alpha_shape:
      if constexpr (Traits::dimension == 3) run_alpha_shape_method<Traits>(result, clock);
      break;
    case Method::power_crust:
      run_power_crust_method<Traits>(result, clock);
      break;
    case Method::boissonnat:
      run_boissonnat_method<Traits>(triangulation, result, clock);
      break;
    case Method::tight_cocone:
      if constexpr (Traits::dimension == 3) {
        run_tight_cocone_method<Traits>(triangulation, result, clock);
      }
      break;
  }

  clock.start("topology");
  result.stats.surface_vertices = result.surface_vertices.size();
  // A result that does not interpolate is measured on its own vertices (all of them used).
  measure_topology<Traits::dimension>(
      result.interpolates() ? samples.size() : result.surface_vertices.size(), result.surface,
      result.stats, checked_skin ? &*checked_skin : nullptr);
  if constexpr (Traits::dimension == 3) find_thin_handles_of(result);
  if (keep) *keep = normalised_poles_of(result);
  undo_normalisation<Traits::dimension>(result, normalisation, samples);
  clock.finish();
  return result;
}

}  // namespace sculpt
