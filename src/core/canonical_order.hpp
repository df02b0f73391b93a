// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles and tetrahedra in one order, whatever produced them: each simplex read from its
// smallest vertex by an even permutation (so its orientation is kept), then the list sorted.
// The methods built on CGAL's own structures (alpha shapes, the Advancing Front) list their
// simplices in an order that follows memory addresses, which change with what a process did
// before; the bytes a run writes must not.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

namespace sculpt {

// The smallest reading of a triangle among its rotations (the even permutations of three).
inline std::array<int, 3> canonical_reading(const std::array<int, 3>& t) {
  const std::array<int, 3> a{t[0], t[1], t[2]}, b{t[1], t[2], t[0]}, c{t[2], t[0], t[1]};
  return std::min({a, b, c});
}

// The smallest reading of a tetrahedron among the twelve even permutations of its vertices.
inline std::array<int, 4> canonical_reading(const std::array<int, 4>& t) {
  static constexpr int even[12][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2},
                                      {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 0, 1, 3}, {2, 1, 3, 0},
                                      {2, 3, 0, 1}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 2, 1, 0}};
  std::array<int, 4> best = t;
  for (const auto& p : even)
    best = std::min(best, std::array<int, 4>{t[p[0]], t[p[1]], t[p[2]], t[p[3]]});
  return best;
}

template <std::size_t K>
void put_in_canonical_order(std::vector<std::array<int, K>>& simplices) {
  for (auto& simplex : simplices) simplex = canonical_reading(simplex);
  std::sort(simplices.begin(), simplices.end());
}

}  // namespace sculpt
