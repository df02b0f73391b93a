// The triangles on every edge of a set of triangles: what the pruning, the walk and the
// bordered rule ask of each edge they cross.
//
// The edges live in an open-addressing hash table, each with its range of one array of
// triangle indices (in increasing order). A map from edge to a vector of its own made an
// allocation per edge and two cache misses per question (bunny00, crust: 0.05 s to build).
#pragma once

#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

namespace sculpt::extraction_detail {

// The same key for (a, b) and (b, a).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
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
    std::size_t capacity = 16;
    shift_ = 60;
    // More slots than edge sides (3 a triangle), so probing always meets an empty one.
    while (capacity <= 3 * triangles.size()) capacity *= 2, --shift_;
    mask_ = capacity - 1;
    slot_key_.assign(capacity, empty);
    slot_edge_.assign(capacity, -1);
    // First the edges and how many triangles each has, then the triangles in their ranges.
    std::vector<int> count;
    for (const auto& t : triangles) {
      for (int j = 0; j < 3; ++j) {
        const std::size_t slot = slot_of(edge_key(t[j], t[(j + 1) % 3]));
        if (slot_edge_[slot] < 0) {
          slot_key_[slot] = edge_key(t[j], t[(j + 1) % 3]);
          slot_edge_[slot] = static_cast<int>(count.size());
          count.push_back(0);
        }
        ++count[slot_edge_[slot]];
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
  int index(int a, int b) const { return slot_edge_[slot_of(edge_key(a, b))]; }
  std::size_t edge_count() const { return first_.size() - 1; }

  Triangles on(int a, int b) const {
    const int e = index(a, b);
    if (e < 0) return {nullptr, nullptr};
    return {triangles_.data() + first_[e], triangles_.data() + first_[e + 1]};
  }

 private:
  static constexpr std::uint64_t empty = ~std::uint64_t{0};  // no edge has both ends at 2^32-1

  // The slot holding `key`, or the empty slot where it would go (linear probing).
  std::size_t slot_of(std::uint64_t key) const {
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
    while (slot_key_[slot] != key && slot_key_[slot] != empty) slot = (slot + 1) & mask_;
    return slot;
  }

  int shift_ = 60;  // the hash: the top bits of a Fibonacci product, as many as the slots need
  std::size_t mask_ = 0;
  std::vector<std::uint64_t> slot_key_;
  std::vector<int> slot_edge_;
  std::vector<int> first_;  // edge e's triangles: triangles_[first_[e] .. first_[e + 1])
  std::vector<int> triangles_;
};

}  // namespace sculpt::extraction_detail
