// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/statistics_json.hpp"

namespace sculpt::frontend {

std::string surface_rule_name(const Options& options, int dimension) {
  if (!sculpts(options.method)) return to_string(options.method);
  if (joins_neighbours(options.method, options.kind, dimension)) return "nearest neighbours";
  if (options.method == Method::robust && options.kind == Surface_kind::bordered) {
    return "openings cut";  // methods/robust/bordered_surface.hpp
  }
  return inserts_poles(options.method, options.kind, dimension) ? to_string(resolved_rule(options))
                                                                : "manifold carve";
}

nlohmann::json statistics_json(const Statistics& stats) {
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& stage : stats.stages) {
    stages.push_back({{"name", stage.name},
                      {"seconds", stage.seconds},
                      {"peak_memory_mib", stage.peak_memory_mib}});
  }
  const Verdict verdict = sculpt::verdict(stats);
  return {
      {"method", to_string(stats.method)},
      {"kind", to_string(stats.kind)},
      {"kind_chosen_automatically", stats.kind_chosen_automatically},
      {"closed_spanning_facets", stats.closed_spanning_facets},
      {"verdict", verdict.line},
      {"manifold", verdict.manifold},
      {"dimension", stats.dimension},
      {"samples", stats.samples},
      {"noise", stats.noise},
      {"cleaned", stats.cleaned},
      {"smoothed", stats.smoothed},
      {"outliers_sought", stats.outliers_sought},
      {"outliers_removed", stats.outliers_removed},
      {"noise_after", stats.noise_after},
      {"cleaning_shift", stats.cleaning_shift},
      {"normalisation",
       {{"translation", stats.translation}, {"scale_exponent", stats.scale_exponent}}},
      {"poles", stats.poles},
      {"convex_poles", stats.convex_poles},
      {"inner_poles", stats.inner_poles},
      {"outer_poles", stats.outer_poles},
      {"unlabelled_poles", stats.unlabelled_poles},
      {"conflicts", stats.conflicts},
      {"conflict_offers", stats.conflict_offers},
      {"carved_cells", stats.carved_cells},
      {"kept_outer_cells", stats.kept_outer_cells},
      {"carved_handles", stats.carved_handles},
      {"refused_handles", stats.refused_handles},
      {"carved_by_flood", stats.carved_by_flood},
      {"inserted_poles", stats.inserted_poles},
      {"delaunay_cells", stats.delaunay_cells},
      {"sculpted_cells", stats.sculpted_cells},
      {"solid_cells", stats.solid_cells},
      {"candidate_facets", stats.candidate_facets},
      {"pruned_facets", stats.pruned_facets},
      {"spanning_facets", stats.spanning_facets},
      {"filled_gaps", stats.filled_gaps},
      {"torn_loops", stats.torn_loops},
      {"short_loops", stats.short_loops},
      {"set_in_samples", stats.set_in_samples},
      {"attached_samples", stats.attached_samples},
      {"joined_pinches", stats.joined_pinches},
      {"dropped_fans", stats.dropped_fans},
      {"closed_notches", stats.closed_notches},
      {"rims_kept", stats.rims_kept},
      {"undersampled_samples", stats.undersampled_samples},
      {"samples_without_umbrella", stats.samples_without_umbrella},
      {"alpha", stats.alpha},
      {"surface_vertices", stats.surface_vertices},
      {"unbounded_power_faces", stats.unbounded_power_faces},
      {"facets", stats.facets},
      {"boundary_ridges", stats.boundary_ridges},
      {"non_manifold_ridges", stats.non_manifold_ridges},
      {"non_manifold_vertices", stats.non_manifold_vertices},
      {"boundary_loops", stats.boundary_loops},
      {"components", stats.components},
      {"euler_characteristic", stats.euler_characteristic},
      {"unused_samples", stats.unused_samples},
      {"thin_handles", stats.thin_handles},
      {"total_seconds", stats.total_seconds},
      {"stages", stages},
  };
}

}  // namespace sculpt::frontend
