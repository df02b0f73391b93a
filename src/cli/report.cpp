// SPDX-License-Identifier: GPL-3.0-or-later
#include "report.hpp"

#include <fmt/format.h>

namespace sculpt::cli {

void print_report(std::ostream& out, const Statistics& stats, const Run_description& run) {
  const bool three = stats.dimension == 3;
  const bool paper = stats.method == Method::paper;
  const bool inserted = inserts_poles(stats.method, stats.kind, stats.dimension);
  out << fmt::format("sculpt {} ({}D, {}, method {}, {}box factor {})\n", run.input,
                     stats.dimension, to_string(stats.kind), to_string(stats.method),
                     inserted || joins_neighbours(stats.method, stats.kind, stats.dimension)
                         ? "rule " + run.rule + ", "
                         : "",
                     run.box_factor);
  out << fmt::format("  {:<14}{:>10}{:>12}\n", "stage", "seconds", "peak MiB");
  out << fmt::format("  {:<14}{:>10.3f}\n", "read", run.read_seconds);
  for (const auto& stage : stats.stages) {
    out << fmt::format("  {:<14}{:>10.3f}{:>12.1f}\n", stage.name, stage.seconds,
                       stage.peak_memory_mib);
  }
  out << fmt::format("  {:<14}{:>10.3f}\n", "total", stats.total_seconds);
  const auto row = [&](const char* name, auto value) {
    out << fmt::format("  {:<28}{:>12}\n", name, value);
  };
  row("samples (n)", stats.samples);
  // -1: not measured (too few samples, or too few a sheet's: thin tubes, thin walls).
  const auto noise = [](double value) {
    return value >= 0 ? fmt::format("{:.3f}", value) : std::string("not measured");
  };
  if (stats.noise >= 0 || stats.cleaned) row("noise (of spacing)", noise(stats.noise));
  if (stats.outliers_sought) {
    row("outliers removed", stats.outliers_removed);
  }
  if (stats.smoothed) {
    row("smoothed (jet): noise after", noise(stats.noise_after));
    row("  moved (of spacing)", fmt::format("{:.3f}", stats.cleaning_shift));
  }
  if (stats.kind_chosen_automatically) {
    row("kind (chosen automatically)", to_string(stats.kind));
    row("closed: facets over openings", stats.closed_spanning_facets);
  }
  const auto& t = stats.translation;
  row("normalised (exactly)",
      fmt::format(
          "{}x 2^{}",
          t[0] || t[1] || t[2] ? fmt::format("(p - ({:g}, {:g}, {:g})) ", t[0], t[1], t[2]) : "p ",
          stats.scale_exponent));
  // Stages 1-2 are skipped by the methods through CGAL, which read neither (stage_plan.hpp).
  const bool shared_stages = stats.delaunay_cells > 0;
  if (shared_stages) row("poles", stats.poles);
  if (sculpts(stats.method)) {  // the crusts label no pole and build no solid
    row("convex poles", stats.convex_poles);
    row("inner / outer poles", fmt::format("{} / {}", stats.inner_poles, stats.outer_poles));
    row("unlabelled poles", stats.unlabelled_poles);
    row(paper ? "conflicts (poles / offers)" : "contradicted poles (poles / offers)",
        fmt::format("{} / {}", stats.conflicts, stats.conflict_offers));
  }
  if (shared_stages) row("cells of DT(S+BBV)", stats.delaunay_cells);
  if (inserted) {
    row(stats.kind == Surface_kind::closed ? "inserted poles (m - 2^D)"
                                           : "inserted poles (l - 2^D)",
        stats.inserted_poles);
    // Bordered, every labelled pole goes in (UP), not only the outer ones (OUP).
    const char* sculpted =
        stats.kind == Surface_kind::closed ? "cells of DT(S+OUP)" : "cells of DT(S+UP)";
    if (stats.sculpted_cells > 0) {
      row(sculpted, stats.sculpted_cells);
    } else {
      row(sculpted, "not built (queries)");
    }
  } else if (sculpts(stats.method)) {
    if (stats.carved_by_flood) {
      row("carved cells (one flood)", stats.carved_cells);
      row("outer cells kept (manifold)", "not counted");
    } else {
      row("carved cells", stats.carved_cells);
      row("outer cells kept (manifold)", stats.kept_outer_cells);
      if (stats.method == Method::robust)
        row(stats.dimension == 3 ? "handles opened (webs removed)" : "holes opened",
            stats.carved_handles);
      if (stats.method == Method::robust && stats.refused_handles > 0)
        row("handles refused (webs kept)", stats.refused_handles);
    }
  }
  if (sculpts(stats.method)) row("solid cells", stats.solid_cells);
  if (stats.method == Method::alpha_shape) row("alpha (radius)", fmt::format("{:g}", stats.alpha));
  if (stats.spanning_facets > 0) row("triangles spanning openings", stats.spanning_facets);
  if (stats.set_in_samples > 0) row("left-off samples set in", stats.set_in_samples);
  if (stats.attached_samples > 0) row("left-off samples attached", stats.attached_samples);
  if (stats.joined_pinches > 0) row("pinched fans joined", stats.joined_pinches);
  if (stats.dropped_fans > 0) row("pinched fans dropped", stats.dropped_fans);
  if (stats.closed_notches > 0) row("sharp border notches closed", stats.closed_notches);
  if (stats.filled_gaps > 0) row("gaps in the sampling filled", stats.filled_gaps);
  if (stats.torn_loops > 0) row("torn loops (not openings)", stats.torn_loops);
  if (stats.short_loops > 0) row("short loops (not openings)", stats.short_loops);
  if (stats.candidate_facets > 0) {
    row("candidates / pruned", fmt::format("{} / {}{}", stats.candidate_facets, stats.pruned_facets,
                                           stats.rims_kept ? " (rims of holes kept)" : ""));
  }
  if (stats.method == Method::cocone || stats.method == Method::tight_cocone) {
    row("undersampled samples", stats.undersampled_samples);
  }
  if (stats.method == Method::tight_cocone) {
    row("samples without umbrella", stats.samples_without_umbrella);
    row("cells not peeled", stats.solid_cells);
  }
  row(three ? "triangles" : "edges", stats.facets);
  row(three ? "boundary edges" : "curve end points", stats.boundary_ridges);
  row(three ? "non-manifold edges" : "branching samples", stats.non_manifold_ridges);
  if (three) row("non-manifold vertices", stats.non_manifold_vertices);
  row(three ? "boundary loops" : "open curves", stats.boundary_loops);
  row("components", stats.components);
  row("Euler characteristic", stats.euler_characteristic);
  if (stats.thin_handles > 0) row("thin handles (suspect)", stats.thin_handles);
  if (stats.surface_vertices > 0) {
    row("vertices (its own)", fmt::format("{} ({:.1f} per sample)", stats.surface_vertices,
                                          double(stats.surface_vertices) / double(stats.samples)));
    row("faces reaching infinity", stats.unbounded_power_faces);
  } else {
    row("unused samples", stats.unused_samples);
  }
}

nlohmann::json report_json(const Statistics& stats, const Run_description& run) {
  nlohmann::json json = frontend::statistics_json(stats);
  json["input"] = run.input;
  json["rule"] = run.rule;
  json["box_factor"] = run.box_factor;
  json["read_seconds"] = run.read_seconds;
  json["write_seconds"] = run.write_seconds;
  return json;
}

}  // namespace sculpt::cli
