// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0 on the samples stage, when the samples were cleaned (driver/cleaning.hpp): where they
// were given, the outliers removed (the surface does not pass through them), and how far the
// smoothing moved each of the others.
#pragma once

#include <sculpt/sculpt.hpp>

#include "../core/without.hpp"
#include "builder_context.hpp"
#include "palette.hpp"

namespace sculpt::scene {

template <int D>
void add_cleaning_layers(const Builder_context<D>& ctx) {
  const Reconstruction<D>& r = ctx.r;
  if (r.given_samples.empty()) return;  // kept with the triangulations only
  Layer& given = ctx.add("given-samples", "samples as given (before cleaning)", Primitive::points,
                         palette::given_sample, D == 2 ? 4 : 2);
  for (const auto& p : r.given_samples) given.positions.push_back(vec(p));
  Layer& outliers = ctx.add("outliers", "outliers removed (not on the surface)", Primitive::points,
                            palette::removed_outlier, D == 2 ? 7 : 5);
  for (int g : r.removed_outliers) outliers.positions.push_back(vec(r.given_samples[g]));
  if (!r.stats.smoothed) return;
  Layer& moves = ctx.add("smoothing", "moved by the smoothing", Primitive::lines,
                         palette::smoothing_move, 1.0f);
  // The cleaned samples are those given but the outliers, in their order.
  const std::vector<Point<D>> kept = without(r.given_samples, r.removed_outliers);
  for (int s = 0; s < static_cast<int>(kept.size()) && s < ctx.n; ++s) {
    moves.positions.push_back(vec(kept[s]));
    moves.positions.push_back(vec(r.sites[s]));
  }
}

}  // namespace sculpt::scene
