// SPDX-License-Identifier: GPL-3.0-or-later
// What a reconstruction will do before it runs: the stages it times, in order (the overall
// progress runs across them), and whether the paper's stages 6-7 build DT(S ∪ OUP).
#pragma once

#include <initializer_list>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

// Whether stages 6-7 need DT(S ∪ OUP) itself: to show it, or for a surface that is not the
// solid's skin (bordered surfaces, the extraction rule: they read the apexes of facets).
inline bool builds_sculpted_delaunay(const Options& options) {
  return options.keep_triangulations || options.kind != Surface_kind::closed ||
         resolved_rule(options) != Surface_rule::skin;
}

// Whether the run builds the stages every method shares, DT(S ∪ BBV) and the poles (stages 1-2).
// The methods through CGAL (the Advancing Front, alpha shapes) build a triangulation of their own
// and read neither: only a run that keeps its triangulations (the viewer, to show every method
// over the same Delaunay triangulation) builds them for those; the command line does not pay for
// what no step reads (bunny00, Advancing Front: 0.19 s of 0.8).
inline bool builds_shared_stages(const Options& options) {
  const bool reads_them =
      options.method != Method::advancing_front && options.method != Method::alpha_shape;
  return reads_them || options.keep_triangulations;
}

// The stages a run times, in order, known before it starts (the method's driver starts them;
// tests/progress_test.cpp checks every method): what the overall progress runs across.
// `first_stages_given`: stages 1-2 come from an earlier attempt (first_stages.hpp).
inline std::vector<const char*> planned_stages(const Options& options, int dimension,
                                               bool first_stages_given = false) {
  std::vector<const char*> stages = {"checks"};
  if (builds_shared_stages(options) && !first_stages_given) {
    stages.insert(stages.end(), {"delaunay", "poles"});
  }
  const auto add = [&](std::initializer_list<const char*> more) {
    stages.insert(stages.end(), more.begin(), more.end());
  };
  // Stages 5-8 of the sculpting methods, from labelled poles.
  const auto sculpt_with_poles = [&] {
    add({builds_sculpted_delaunay(options) ? "insertion" : "queries", "solid", "surface"});
  };
  switch (options.method) {
    case Method::paper:
      add({"seeds", "propagation"});
      sculpt_with_poles();
      break;
    case Method::robust:
      add({"seeds", "labelling"});
      if (joins_neighbours(Method::robust, options.kind, dimension)) {
        add({"surface"});
      } else if (inserts_poles(Method::robust, options.kind, dimension)) {
        sculpt_with_poles();
        add({"openings", "pruning", "walk", "mending"});  // robust/bordered_surface.hpp
      } else {
        add({"carving", "solid", "surface"});
      }
      break;
    case Method::crust:
      if (dimension == 2) {
        add({"voronoi", "crust", "surface"});
      } else {
        add({"crust", "filtering", "pruning", "walk"});
      }
      break;
    case Method::nn_crust:
      add({"surface"});
      break;
    case Method::cocone:
      add({"cocone", "undersampling", "pruning", "walk"});
      break;
    case Method::tight_cocone:
      add({"cocone", "undersampling", "pruning", "walk", "peeling", "solid", "surface"});
      break;
    case Method::power_crust:
      add({"seeds", "labelling", "power diagram", "power-crust"});
      break;
    case Method::advancing_front:
      add({"advancing-front"});
      break;
    case Method::alpha_shape:
      add({"alpha-shape", "surface"});
      break;
    case Method::boissonnat:
      add({"sculpting", "solid", "surface"});
      break;
  }
  stages.push_back("topology");
  return stages;
}

}  // namespace sculpt
