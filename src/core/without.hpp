// SPDX-License-Identifier: GPL-3.0-or-later
// A list with some of its items taken out by index: the samples a cleaning keeps, and whatever
// goes with them (their normals and colours, where they were given).
#pragma once

#include <algorithm>
#include <vector>

namespace sculpt {

// The items but those listed (increasing indices), in their order.
template <class T>
std::vector<T> without(const std::vector<T>& items, const std::vector<int>& gone) {
  std::vector<T> kept;
  kept.reserve(items.size() - std::min(items.size(), gone.size()));
  auto next_gone = gone.begin();
  for (int i = 0; i < static_cast<int>(items.size()); ++i) {
    if (next_gone != gone.end() && *next_gone == i) {
      ++next_gone;
    } else {
      kept.push_back(items[i]);
    }
  }
  return kept;
}

}  // namespace sculpt
