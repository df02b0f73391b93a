// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 3, shared by every method: the seeds of the pole labelling (section 3.1.1). The convex
// poles, whose cells touch a corner of the box, lie outside any surface of the samples. A closed
// surface starts from all of them; a bordered one (section 4) from a single convex pole, since
// its two sides meet around the border and only one side can be known for sure.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt {

inline Label opposite(Label label) {
  return label == Label::inner ? Label::outer : Label::inner;
}

template <int D>
int choose_bordered_seed(const Reconstruction<D>& result) {
  const auto& stage = result.poles;
  const auto is_convex = [&](int pole) { return pole >= 0 && stage.poles[pole].convex; };
  const int requested = result.options.bordered_seed_sample;
  const int n = static_cast<int>(stage.positive_pole.size());
  if (requested >= 0) {
    if (requested >= n) {
      throw Input_error("the bordered seed sample " + std::to_string(requested) +
                        " is not a sample (there are " + std::to_string(n) + ")");
    }
    if (is_convex(stage.positive_pole[requested])) return stage.positive_pole[requested];
    if (is_convex(stage.negative_pole[requested])) return stage.negative_pole[requested];
    throw Input_error("sample " + std::to_string(requested) +
                      " has no convex pole to seed a bordered surface");
  }
  for (int s = 0; s < n; ++s) {
    if (is_convex(stage.positive_pole[s])) return stage.positive_pole[s];
  }
  return -1;
}

template <int D>
void select_seeds(Reconstruction<D>& result) {
  auto& seeds = result.seeds;
  const auto& poles = result.poles.poles;
  for (int p = 0; p < static_cast<int>(poles.size()); ++p) {
    if (poles[p].convex) seeds.convex_poles.push_back(p);
  }
  if (result.options.kind == Surface_kind::closed) {
    seeds.outer_seeds = seeds.convex_poles;
  } else if (const int seed = choose_bordered_seed(result); seed >= 0) {
    seeds.outer_seeds = {seed};
  }
}

}  // namespace sculpt
