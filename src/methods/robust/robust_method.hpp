// SPDX-License-Identifier: GPL-3.0-or-later
// The robust method, after the shared stages 1-3 (Delaunay, poles, seeds):
//   4.  labelling   poles labelled by confidence (confidence_labelling.hpp)
//   6b. carving     the hull's all-sample cells carved from the outside in, keeping a
//                   2-manifold (manifold_carving.hpp), each judged (cell_classification.hpp)
//                   when the carving first asks about it
//   7.  solid       the cells left
//   8.  surface     the facets between the solid and the outside
// No pole is inserted: a cell judged outer is removed directly, so DT(S ∪ OUP) is never built.
// Bordered curves (section 4, in 2D) join each sample to its nearest neighbours and end where the
// samples end (open_curves.hpp). Bordered surfaces take the paper's DT(S ∪ BBV ∪ UP) (built anew
// from every site, not by insertion: pole_insertion.hpp) and its extraction rule, with the
// confidence labels, as candidates; the triangles spanning an opening
// go, and the rest is made a manifold (bordered_surface.hpp):
//   6d. openings    the triangles wider than the samples' spacing there removed
//   6e. pruning, walk  the manifold extraction of the candidates left
//   6f. mending     samples left off attached, sharp notches closed, small loops that are gaps
//                   filled (left_off_samples.hpp, gap_filling.hpp)
#pragma once

#include <optional>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/label_statistics.hpp"
#include "../../core/stage_clock.hpp"
#include "../paper/paper_method.hpp"
#include "bordered_surface.hpp"
#include "cell_classification.hpp"
#include "confidence_labelling.hpp"
#include "manifold_carving.hpp"
#include "open_curves.hpp"

namespace sculpt {

// Returns the surface's check as a closed 2-manifold through every sample when the carving made
// it (its flood stood), for the topology stage.
template <class Traits>
std::optional<Skin_check> run_robust_method(typename Traits::Triangulation& triangulation,
                                            Reconstruction<Traits::dimension>& result,
                                            Stage_clock& clock) {
  clock.start("labelling");
  label_poles_by_confidence(result, clock);
  count_labels(result);

  if constexpr (Traits::dimension == 2) {
    if (joins_neighbours(Method::robust, result.options.kind, 2)) {
      clock.start("surface");
      result.surface =
          open_curves(triangulation, result.sites, static_cast<int>(result.sample_count()));
      return std::nullopt;
    }
  }
  if (inserts_poles(Method::robust, result.options.kind, Traits::dimension)) {
    sculpt_with_poles<Traits>(triangulation, result, clock, Sculpted_by::rebuilding);
    if constexpr (Traits::dimension == 3) {
      open_borders({result.sites.begin(), result.sites.begin() + result.sample_count()}, result,
                   clock);
    }
    return std::nullopt;
  }

  clock.start("carving");
  const Cell_judge<Traits> judge(triangulation, result);
  Manifold_carving<Traits> carving(triangulation, result, judge, clock);
  carving.run();
  result.stats.carved_cells = carving.removed();
  result.stats.kept_outer_cells = result.carving.kept_outer_cells.size();

  clock.start("solid");
  carving.collect_solid();
  clock.start("surface");
  carving.collect_surface();
  return carving.checked_skin();
}

}  // namespace sculpt
