// SPDX-License-Identifier: GPL-3.0-or-later
// The border of an oriented set of triangles: the edges on one triangle only, each directed as
// its triangle has it, with the triangle's third vertex. Mending a bordered surface starts from
// it: the front over the left-off samples, the notches, the gaps (left_off_samples.hpp,
// gap_filling.hpp).
#pragma once

#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/key_table.hpp"
#include "../extraction/edge_map.hpp"
#include "../extraction/manifold_extraction.hpp"
#include "../extraction/vector3.hpp"

namespace sculpt {

// How many triangles each edge is on, by edge_key.
using Edge_uses = Key_table<int>;

inline Edge_uses edge_uses(const std::vector<Facet<3>>& triangles) {
  Edge_uses uses;
  uses.reserve(extraction_detail::expected_edge_count(triangles.size()));
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) ++uses[edge_key(t[j], t[(j + 1) % 3])];
  }
  return uses;
}

// Per directed edge a -> b of a triangle (directed_key), the triangle's third vertex. On an
// oriented surface an edge's uses are those of its two directions.
using Third_vertex = Key_table<int>;

// The end w of the border edge v -> w leaving the fan of triangles around v that the border edge
// u -> v arrives in: around v from the triangle on u -> v, across one edge at v after another,
// until the fan ends. -1 around a closed fan (after `most` steps). `third` needs the triangles at
// v only.
inline int fan_end(const Third_vertex& third, int u, int v, std::size_t most) {
  int x = third.at(directed_key(u, v));
  for (std::size_t steps = 0; steps < most; ++steps) {
    const int* next = third.find(directed_key(x, v));
    if (!next) return x;
    x = *next;
  }
  return -1;
}

// Whether the triangle (w, v, u) that closes the border corner u -> v -> w faces as the
// triangles it leans on: (u, v, u_apex) on u -> v and (v, w, w_apex) on v -> w (the notches of
// left_off_samples.hpp, the joins of pinched_vertices.hpp).
inline bool closes_corner_facing_on(const std::vector<Point<3>>& samples, int u, int v, int w,
                                    int u_apex, int w_apex) {
  using extraction_detail::dot;
  using extraction_detail::normal_of;
  const auto normal = normal_of(samples, w, v, u);
  return dot(normal, normal_of(samples, u, v, u_apex)) > 0 &&
         dot(normal, normal_of(samples, v, w, w_apex)) > 0;
}

struct Border_edge {
  int from, to, apex;  // the triangle (from, to, apex)
};

// The edges on one triangle only, in the order of the triangles.
inline std::vector<Border_edge> border_edges(const std::vector<Facet<3>>& triangles,
                                             const Edge_uses& uses) {
  std::vector<Border_edge> border;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) {
      const int a = t[j], b = t[(j + 1) % 3];
      if (uses.at(edge_key(a, b)) == 1) border.push_back({a, b, t[(j + 2) % 3]});
    }
  }
  return border;
}

}  // namespace sculpt
