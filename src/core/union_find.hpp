// SPDX-License-Identifier: GPL-3.0-or-later
// Disjoint sets over 0..size-1 (union-find with path halving): the connected pieces of a
// surface's vertices, of a vertex's link, of border edges.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace sculpt {

class Union_find {
 public:
  explicit Union_find(std::size_t size) : parent_(size) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // Joins the sets of a and b; whether they were apart.
  bool unite(std::size_t a, std::size_t b) {
    const std::size_t root_a = find(a), root_b = find(b);
    parent_[root_a] = root_b;
    return root_a != root_b;
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace sculpt
