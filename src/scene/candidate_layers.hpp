// SPDX-License-Identifier: GPL-3.0-or-later
// The filtering methods' candidates (the crust's and the co-cones' in 3D), drawn on the
// candidates stage: the triangles kept, those the pruning removed (all, or a replay's first
// steps) and the samples the co-cones mark. Its own file: a stage of those methods only, with a
// replay of its own.
#pragma once

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "builder_context.hpp"
#include "layer_helpers.hpp"
#include "palette.hpp"
#include "scene.hpp"

namespace sculpt::scene {

// The triangles a filtering method chose (shaded) and those the pruning removed (red edges):
// the surface is the outer boundary of the shaded ones.
// The candidates, and those pruned: all of them, or (a replay) the first `step` in the order
// the pruning took them, the last of those lit.
template <int D>
void candidates(const Builder_context<D>& ctx) {
  const auto& candidates = ctx.r.candidates;
  const std::size_t shown = ctx.request.step < 0
                                ? candidates.pruned.size()
                                : std::min<std::size_t>(ctx.request.step, candidates.pruned.size());
  if (shown < candidates.pruned.size())
    ctx.scene.title +=
        ", pruned " + std::to_string(shown) + " of " + std::to_string(candidates.pruned.size());
  Layer& kept = ctx.add(
      "candidates", "candidates kept (" + std::to_string(candidates.chosen.size() - shown) + ")",
      Primitive::triangles, palette::solid, 1.0f);
  kept.lit = true;
  std::vector<Facet<D>> pruned(candidates.pruned.begin(), candidates.pruned.begin() + long(shown));
  for (auto& f : pruned) std::sort(f.begin(), f.end());
  std::sort(pruned.begin(), pruned.end());
  for (const auto& facet : candidates.chosen) {
    auto sorted = facet;
    std::sort(sorted.begin(), sorted.end());
    if (std::binary_search(pruned.begin(), pruned.end(), sorted)) continue;
    for (int v : facet) kept.positions.push_back(vec(ctx.r.sites[v]));
  }
  if (shown > 0) {
    Layer& removed =
        ctx.add("pruned",
                std::string(candidates.rims_kept ? "pruned, rims of holes kept (" : "pruned (") +
                    std::to_string(shown) + ")",
                Primitive::lines, palette::non_manifold, 2.0f);
    for (std::size_t i = 0; i < shown; ++i) {
      const auto& facet = candidates.pruned[i];
      for (int j = 0; j < D; ++j) {
        removed.positions.push_back(vec(ctx.r.sites[facet[j]]));
        removed.positions.push_back(vec(ctx.r.sites[facet[(j + 1) % D]]));
      }
    }
  }
  // During the replay, the triangle the step prunes, filled where the eye must go.
  if (ctx.request.step > 0 && shown > 0) {
    Layer& now = ctx.add("just-removed", "pruned at this step", Primitive::triangles,
                         palette::just_removed, 1.0f);
    for (int v : candidates.pruned[shown - 1]) now.positions.push_back(vec(ctx.r.sites[v]));
  }
  // The samples the co-cone does not trust, and those the tight co-cone found no umbrella at.
  const auto marked = [&](const char* id, const std::string& title, const std::vector<int>& samples,
                          Color color) {
    if (samples.empty()) return;
    Layer& layer = ctx.add(id, title + " (" + std::to_string(samples.size()) + ")",
                           Primitive::points, color, 7.0f);
    for (int s : samples) layer.positions.push_back(vec(ctx.r.sites[s]));
  };
  marked("undersampled", "undersampled samples", candidates.undersampled, palette::undersampled);
  marked("without-umbrella", "samples without umbrella", candidates.without_umbrella,
         palette::without_umbrella);
}

}  // namespace sculpt::scene
