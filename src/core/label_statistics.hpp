// SPDX-License-Identifier: GPL-3.0-or-later
// The label counts of the statistics, the same for every method's pole labelling.
#pragma once

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <vector>

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

}  // namespace sculpt
