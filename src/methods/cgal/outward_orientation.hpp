// SPDX-License-Identifier: GPL-3.0-or-later
// A consistently oriented closed surface bounds a positive volume when its normals point
// outward: the surfaces made by other libraries are turned that way, as ours are, one connected
// piece at a time (a piece with a border bounds no volume and is left as it is).
#pragma once

#include <algorithm>
#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/union_find.hpp"
#include "../extraction/edge_map.hpp"

namespace sculpt {

inline void orient_outward(const std::vector<Point<3>>& points, std::vector<Facet<3>>& surface) {
  // The pieces: vertices joined by the triangles.
  Union_find pieces(points.size());
  for (const auto& t : surface) {
    pieces.unite(t[1], t[0]);
    pieces.unite(t[2], t[0]);
  }
  const auto root = [&](int v) { return pieces.find(static_cast<std::size_t>(v)); };
  // Per piece (by its root): six times its signed volume (tetrahedra from the origin to each
  // triangle), and whether every edge has one triangle on each side, used once each way round.
  std::vector<double> six_volume(points.size(), 0.0);
  std::vector<char> closed(points.size(), 1);
  std::vector<std::uint64_t> directed_edges;  // sorted
  directed_edges.reserve(3 * surface.size());
  for (const auto& t : surface) {
    const auto &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    six_volume[root(t[0])] += a[0] * (b[1] * c[2] - b[2] * c[1]) -
                              a[1] * (b[0] * c[2] - b[2] * c[0]) +
                              a[2] * (b[0] * c[1] - b[1] * c[0]);
    for (int k = 0; k < 3; ++k) directed_edges.push_back(directed_key(t[k], t[(k + 1) % 3]));
  }
  std::sort(directed_edges.begin(), directed_edges.end());
  for (std::size_t e = 0; e < directed_edges.size(); ++e) {
    const auto edge = directed_edges[e];
    const int from = static_cast<int>(edge >> 32), to = static_cast<int>(edge & 0xffffffffu);
    const bool once = (e == 0 || directed_edges[e - 1] != edge) &&
                      (e + 1 == directed_edges.size() || directed_edges[e + 1] != edge);
    if (!once ||
        !std::binary_search(directed_edges.begin(), directed_edges.end(), directed_key(to, from))) {
      closed[root(from)] = 0;
    }
  }
  for (auto& t : surface) {
    const std::size_t piece = root(t[0]);
    if (closed[piece] && six_volume[piece] < 0) std::swap(t[1], t[2]);
  }
}

}  // namespace sculpt
