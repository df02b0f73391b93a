// The robust method's rule for bordered surfaces: borders where the samples end.
//
// The paper's bordered rule (section 4: insert every pole, keep the all-sample facets with an
// outer apex) keeps a sheet, but across an opening the apexes are box corners or poles of the
// same side, so the opening is capped: a hemisphere comes out nearly closed. The triangles of
// such a cap are far wider than the gaps between the samples around them
// (core/spanning_openings.hpp), so they go, and what is left is made a manifold:
//
//   candidates <- the paper's bordered surface, with the confidence labels
//   spanning   <- the candidates wider than ρ times the samples' spacing there
//   surface    <- manifold extraction of candidates - spanning (prune sharp edges, walk the
//                 outer boundary: methods/extraction/manifold_extraction.hpp)
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/spanning_openings.hpp"
#include "../../core/stage_clock.hpp"
#include "../extraction/manifold_extraction.hpp"

namespace sculpt {

// From the paper's bordered surface in result.surface to the robust one; the candidates stage
// keeps both sets.
inline void open_borders(const std::vector<Point<3>>& samples, Reconstruction<3>& result,
                         Stage_clock& clock) {
  clock.start("openings");
  const std::vector<double> spacing = sample_spacings<3>(samples);
  auto& candidates = result.candidates;
  candidates.chosen.clear();
  candidates.spanning.clear();
  for (const auto& triangle : result.surface) {
    (spans_opening<3>(samples, spacing, triangle) ? candidates.spanning : candidates.chosen)
        .push_back(triangle);
  }
  result.stats.spanning_facets = candidates.spanning.size();
  extract_manifold(samples, result, clock);
}

}  // namespace sculpt
