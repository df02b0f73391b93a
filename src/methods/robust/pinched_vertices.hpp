// Pinched vertices of a bordered surface, joined. Where the extraction leaves holes close
// together, two fans of triangles can meet at one vertex and nowhere else, as a bow tie does:
// the surface is not a manifold there (CGAL's ChineseDragon --bordered: 96 such vertices, most
// of them two fans of 1 to 4 triangles). Each gap between two fans at such a vertex v is bounded
// by a border edge u -> v arriving from one fan and one v -> w leaving the other; a triangle
// (w, v, u) closes it and makes the two fans one:
//
//   repeat while some vertex was joined:
//     for each vertex v with two or more border edges arriving (so more than one fan):
//       among the pairs u -> v, v -> w (u != w, w not the end of u's own fan) where (w, v, u)
//         may be added (not wider than the mending allows, u-w no edge yet or the border edge
//         w -> u, facing as the triangles on u-v and v-w do), the one of smallest angle at v:
//         add (w, v, u)
//
// The triangle leans on two border edges, so u and w stay manifold. Measured (scripts/measure-
// borders): ChineseDragon --bordered 96 -> 46 non-manifold vertices and 52 -> 30 loops, the
// shared distcap scan 17 -> 9, cylinder_locally_refined 4 -> 3; a wavy 20k sheet with noise of
// 5% of the spacing 63 -> 21. The rest are fans that fold against each other, or whose gap has
// its u-w edge inside the surface already: no triangle can join them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <vector>

#include "../extraction/vector3.hpp"
#include "border_edges.hpp"

namespace sculpt {


// Joins the fans at pinched vertices of `surface`; returns how many triangles it added.
inline std::size_t join_pinched_vertices(const std::vector<Point<3>>& samples,
                                         std::vector<Facet<3>>& surface,
                                         const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::cross;
  using extraction_detail::dot;
  using extraction_detail::edge_key;
  using extraction_detail::minus;
  struct Side {
    int other, apex;  // the border edge's other end, and its triangle's third vertex
  };
  std::size_t joined = 0;
  for (bool progress = true; progress;) {
    progress = false;
    const Edge_uses uses = edge_uses(surface);
    // Per directed edge a -> b of a triangle, its third vertex.
    std::unordered_map<std::uint64_t, int> third;
    for (const auto& t : surface) {
      for (int j = 0; j < 3; ++j) third[directed_key(t[j], t[(j + 1) % 3])] = t[(j + 2) % 3];
    }
    // The end w of the border edge v -> w leaving the fan that u -> v arrives in: around v from
    // the triangle on u -> v, across one edge at v after another, until the fan ends.
    const auto fan_end = [&](int u, int v) {
      int x = third.at(directed_key(u, v));
      for (std::size_t steps = 0; steps < surface.size(); ++steps) {
        const auto next = third.find(directed_key(x, v));
        if (next == third.end()) return x;
        x = next->second;
      }
      return -1;  // around a closed fan: no end
    };
    std::unordered_map<int, std::vector<Side>> arriving, leaving;
    for (const auto& [a, b, c] : border_edges(surface, uses)) {
      leaving[a].push_back({b, c});
      arriving[b].push_back({a, c});
    }
    std::vector<int> pinched;
    for (const auto& [v, sides] : arriving) {
      if (sides.size() > 1) pinched.push_back(v);
    }
    std::sort(pinched.begin(), pinched.end());  // the same triangles, run to run
    std::vector<char> touched(samples.size(), 0);
    for (int v : pinched) {
      if (touched[v]) continue;
      double best_cosine = -2;
      Facet<3> best{};
      for (const Side& in : arriving[v]) {
        for (const Side& out : leaving[v]) {
          const int u = in.other, w = out.other;
          if (u == w || touched[u] || touched[w]) continue;
          // u-w may be an edge already only as a border edge w -> u: the triangle closes a loop.
          const auto used = uses.find(edge_key(u, w));
          if (used != uses.end() && (used->second != 1 || !third.count(directed_key(w, u))))
            continue;
          if (fan_end(u, v) == w) continue;  // that would close u's own fan, not join two
          const auto to_u = minus(samples[u], samples[v]), to_w = minus(samples[w], samples[v]);
          const double lengths = std::sqrt(dot(to_u, to_u) * dot(to_w, to_w));
          if (!(lengths > 0)) continue;
          const double cosine = dot(to_u, to_w) / lengths;
          if (cosine <= best_cosine) continue;
          const auto normal = cross(minus(samples[v], samples[w]), minus(samples[u], samples[w]));
          const auto leaned_u =
              cross(minus(samples[v], samples[u]), minus(samples[in.apex], samples[u]));
          const auto leaned_w =
              cross(minus(samples[w], samples[v]), minus(samples[out.apex], samples[v]));
          if (dot(normal, leaned_u) <= 0 || dot(normal, leaned_w) <= 0) continue;
          if (not_to_add({w, v, u})) continue;
          best_cosine = cosine;
          best = {w, v, u};
        }
      }
      if (best_cosine < -1) continue;
      surface.push_back(best);
      for (int x : best) touched[x] = 1;
      ++joined;
      progress = true;
    }
  }
  return joined;
}

}  // namespace sculpt
