// SPDX-License-Identifier: GPL-3.0-or-later
// The robust method's rule for bordered surfaces: borders where the samples end.
//
// The paper's bordered rule (section 4: insert every pole, keep the all-sample facets with an
// outer apex) keeps a sheet, but across an opening the apexes are box corners or poles of the
// same side, so the opening is capped: a hemisphere comes out nearly closed. The triangles of
// such a cap are far wider than the gaps between the samples around them
// (core/spanning_openings.hpp), so they go, and what is left is made a manifold:
//
//   candidates <- the paper's bordered surface, with the confidence labels
//   spanning   <- the candidates wider than ρ = 3 times the samples' spacing there (the median
//                 over each vertex's neighbourhood, so that rim samples count) whose circle's
//                 middle is empty, and, grown from them across edges, those wider than 2 times
//   surface    <- manifold extraction of candidates - spanning (prune sharp edges, walk the
//                 outer boundary: methods/extraction/manifold_extraction.hpp)
//   mending    <- samples left off beneath a triangle set into it, or into an edge, or over a
//                 corner given the corner's place (samples_under_triangles.hpp),
//                 the others attached to the border, its sharp notches closed
//                 (left_off_samples.hpp), fans pinched at a vertex joined, small border loops
//                 that are gaps, not openings, filled (gap_filling.hpp), then the smaller fans
//                 still pinched dropped and the loops left, through pinches too, filled where
//                 they are gaps
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/spanning_openings.hpp"
#include "../../core/stage_clock.hpp"
#include "../extraction/manifold_extraction.hpp"
#include "gap_filling.hpp"
#include "left_off_samples.hpp"
#include "pinched_vertices.hpp"
#include "samples_under_triangles.hpp"

namespace sculpt {

// An opening found grows over the triangles next to it wider than this many spacings: its rim
// samples see neighbours on one side only, which makes their spacing look larger, so the
// triangles along the rim measure less than the opening's middle (the hysteresis of an edge
// detector: strong evidence starts an opening, weaker evidence extends it). Below 2 legitimate
// triangles of jittered samples would go too (up to 1.84 on the closed test shapes).
inline constexpr double opening_growth_ratio = 2.0;

// From the paper's bordered surface in result.surface to the robust one; the candidates stage
// keeps both sets.
inline void open_borders(const std::vector<Point<3>>& samples, Reconstruction<3>& result,
                         Stage_clock& clock) {
  clock.start("openings");
  const Point_tree<3> tree(samples.data(), samples.data() + samples.size());
  const std::vector<double> spacing = neighbourhood_spacings(samples, tree);
  const auto over_opening = [&](const Facet<3>& facet, double ratio) {
    return spans_opening<3>(samples, spacing, facet, ratio) &&
           !circle_middle_on_the_sheet(samples, tree, facet);
  };
  auto& candidates = result.candidates;
  candidates.chosen.clear();
  candidates.spanning.clear();
  const auto& triangles = result.surface;
  const extraction_detail::Edge_map edges(triangles);
  std::vector<char> removed(triangles.size(), 0);
  std::vector<int> queue;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    if (over_opening(triangles[t], opening_ratio<3>)) {
      removed[t] = 1;
      queue.push_back(t);
    }
  }
  while (!queue.empty()) {
    const int t = queue.back();
    queue.pop_back();
    for (int j = 0; j < 3; ++j) {
      for (int u : edges.on(triangles[t][j], triangles[t][(j + 1) % 3])) {
        if (removed[u]) continue;
        if (over_opening(triangles[u], opening_growth_ratio)) {
          removed[u] = 1;
          queue.push_back(u);
        }
      }
    }
  }
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    (removed[t] ? candidates.spanning : candidates.chosen).push_back(triangles[t]);
  }
  result.stats.spanning_facets = candidates.spanning.size();
  // Borders are expected: the rims are kept from the start (pruning them would eat the sheet).
  extract_manifold(samples, result, clock, Rims::kept);
  // Mending the border, only where the spacing is known (not with fewer samples than it counts).
  // A triangle reaching out to a left-off sample or across a notch may not be wider than the
  // growth ratio allows, however full the middle of its circle: that waiver, for slivers amid
  // the sheet, would let a triangle reach far out to samples off it. Inside a small loop a
  // sliver along the sheet is what the loop needs: a fill is refused only where its triangles
  // cover a disc empty of samples.
  clock.start("mending");
  const auto spacing_unknown = [&](const Facet<3>& facet) {
    return !std::isfinite(spacing[facet[0]]) || !std::isfinite(spacing[facet[1]]) ||
           !std::isfinite(spacing[facet[2]]);
  };
  const auto too_wide = [&](const Facet<3>& facet) {
    return spacing_unknown(facet) ||
           spans_opening<3>(samples, spacing, facet, opening_growth_ratio);
  };
  // A fill is any triangulation of its loop, not a Delaunay one: an obtuse triangle's circle can
  // reach over the sheet while its body spans a hole, so the discs it covers are measured.
  const auto covers_an_opening = [&](const Facet<3>& facet) {
    return spacing_unknown(facet) ||
           covers_an_empty_disc(samples, tree, spacing, facet, opening_growth_ratio);
  };
  result.stats.set_in_samples = set_in_left_off_samples(samples, result.surface);
  result.stats.attached_samples = attach_left_off_samples(samples, result.surface, too_wide);
  result.stats.closed_notches = close_border_notches(samples, result.surface, too_wide);
  result.stats.joined_pinches = join_pinched_vertices(samples, result.surface, too_wide);
  result.stats.filled_gaps =
      fill_gaps(samples, result.surface, covers_an_opening, Pinches::left_out).filled;
  // Fans no triangle could join: the smaller ones go, and the loops that leaves may be gaps; so
  // may the loops between the fans that stay (a small fan folded back over the surface would
  // leave its loop folded too if filled around first).
  result.stats.dropped_fans = drop_pinched_fans(result.surface, samples.size());
  const Gaps_filled last = fill_gaps(samples, result.surface, covers_an_opening);
  result.stats.filled_gaps += last.filled;
  result.stats.torn_loops = last.torn_loops;
  result.stats.short_loops = last.short_loops;
}

}  // namespace sculpt
