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
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace sculpt
