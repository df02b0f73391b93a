// SPDX-License-Identifier: GPL-3.0-or-later
// The triangles on every edge of a set of triangles: what the pruning, the walk and the
// bordered rule ask of each edge they cross.
//
// The edges are numbered in a key table (core/key_table.hpp), each with its range of one array
// of triangle indices (in increasing order). A map from edge to a vector of its own made an
// allocation per edge and two cache misses per question (bunny00, crust: 0.05 s to build).
#pragma once

#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/edge_keys.hpp"
#include "../../core/key_table.hpp"

namespace sculpt::extraction_detail {

// How many edges a surface of this many triangles has, about: a closed one's, and some border.
inline std::size_t expected_edge_count(std::size_t triangles) {
  return 3 * triangles / 2 + 16;
}

class Edge_map {
 public:
  // The triangles of an edge, in increasing order.
  struct Triangles {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
  };

  explicit Edge_map(const std::vector<Facet<3>>& triangles) {
    numbers_.reserve(expected_edge_count(triangles.size()));
    // First the edges, numbered as met, and how many triangles each has; then the triangles in
    // their ranges.
    std::vector<int> count;
    for (const auto& t : triangles) {
      for (int j = 0; j < 3; ++j) {
        int& number = numbers_[edge_key(t[j], t[(j + 1) % 3])];
        if (number == 0) {
          count.push_back(0);
          number = static_cast<int>(count.size());
        }
        ++count[number - 1];
      }
    }
    first_.assign(count.size() + 1, 0);
    for (std::size_t e = 0; e < count.size(); ++e) first_[e + 1] = first_[e] + count[e];
    triangles_.resize(first_.back());
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      for (int j = 0; j < 3; ++j) {
        triangles_[fill[index(triangles[t][j], triangles[t][(j + 1) % 3])]++] = t;
      }
    }
  }

  // The edge's number among the edges (0 .. edge_count() - 1), or -1 if no triangle has it.
  int index(int a, int b) const {
    const int* number = numbers_.find(edge_key(a, b));
    return number ? *number - 1 : -1;
  }
  std::size_t edge_count() const { return first_.size() - 1; }

  Triangles on(int a, int b) const {
    const int e = index(a, b);
    if (e < 0) return {nullptr, nullptr};
    return {triangles_.data() + first_[e], triangles_.data() + first_[e + 1]};
  }

 private:
  Key_table<int> numbers_;  // by edge_key: the edge's number + 1
  std::vector<int> first_;  // edge e's triangles: triangles_[first_[e] .. first_[e + 1])
  std::vector<int> triangles_;
};

}  // namespace sculpt::extraction_detail
