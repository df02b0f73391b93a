// A consistently oriented closed surface bounds a positive volume when its normals point
// outward: the surfaces made by other libraries are turned that way, as ours are, one connected
// piece at a time (a piece with a border bounds no volume and is left as it is).
#pragma once

#include <map>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/union_find.hpp"

namespace sculpt {

inline void orient_outward(const std::vector<Point<3>>& points, std::vector<Facet<3>>& surface) {
  // The pieces: vertices joined by the triangles.
  Union_find pieces(points.size());
  for (const auto& t : surface) {
    pieces.unite(t[1], t[0]);
    pieces.unite(t[2], t[0]);
  }
  const auto root = [&](int v) { return static_cast<int>(pieces.find(v)); };
  // Per piece: six times its signed volume (tetrahedra from the origin to each triangle), and
  // whether every edge has a triangle on its other side.
  std::map<int, double> six_volume;
  std::map<std::pair<int, int>, int> directed_edges;
  for (const auto& t : surface) {
    const auto &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    six_volume[root(t[0])] += a[0] * (b[1] * c[2] - b[2] * c[1]) -
                              a[1] * (b[0] * c[2] - b[2] * c[0]) +
                              a[2] * (b[0] * c[1] - b[1] * c[0]);
    for (int k = 0; k < 3; ++k) ++directed_edges[{t[k], t[(k + 1) % 3]}];
  }
  std::map<int, bool> closed;
  for (const auto& t : surface) closed.emplace(root(t[0]), true);
  for (const auto& [edge, count] : directed_edges) {
    if (count != 1 || !directed_edges.count({edge.second, edge.first})) {
      closed[root(edge.first)] = false;
    }
  }
  for (auto& t : surface) {
    const int piece = root(t[0]);
    if (closed[piece] && six_volume[piece] < 0) std::swap(t[1], t[2]);
  }
}

}  // namespace sculpt
