// SPDX-License-Identifier: GPL-3.0-or-later
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
// its u-w edge inside the surface already: no triangle can join them. Those are separated
// (drop_pinched_fans, below): ChineseDragon 46 -> 0 and, with the gaps that leaves filled,
// 30 -> 19 loops; cylinder_locally_refined 3 -> 0 and 3 -> 1 loop (its truth); distcap 9 -> 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <vector>

#include "../../core/union_find.hpp"
#include "../extraction/vector3.hpp"
#include "border_edges.hpp"

namespace sculpt {

// Joins the fans at pinched vertices of `surface`; returns how many triangles it added.
inline std::size_t join_pinched_vertices(const std::vector<Point<3>>& samples,
                                         std::vector<Facet<3>>& surface,
                                         const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::cross;
  using extraction_detail::dot;
  using extraction_detail::minus;
  struct Side {
    int other, apex;  // the border edge's other end, and its triangle's third vertex
  };
  std::size_t joined = 0;
  // Per directed edge a -> b of a triangle, its third vertex: the surface is oriented, so an
  // edge's uses are those of its two directions. Kept up to date as triangles are added, as are
  // the border edges arriving at and leaving each vertex.
  Third_vertex third;
  third.reserve(3 * surface.size());
  for (const auto& t : surface) {
    for (int j = 0; j < 3; ++j) third[directed_key(t[j], t[(j + 1) % 3])] = t[(j + 2) % 3];
  }
  const auto uses = [&](int a, int b) {
    return int(third.count(directed_key(a, b))) + int(third.count(directed_key(b, a)));
  };
  std::unordered_map<int, std::vector<Side>> arriving, leaving;
  for (const auto& t : surface) {
    for (int j = 0; j < 3; ++j) {
      const int a = t[j], b = t[(j + 1) % 3];
      if (third.count(directed_key(b, a))) continue;
      leaving[a].push_back({b, t[(j + 2) % 3]});
      arriving[b].push_back({a, t[(j + 2) % 3]});
    }
  }
  const auto add = [&](const Facet<3>& t) {
    surface.push_back(t);
    for (int j = 0; j < 3; ++j) {
      const int a = t[j], b = t[(j + 1) % 3], c = t[(j + 2) % 3];
      third[directed_key(a, b)] = c;
      if (third.count(directed_key(b, a))) {  // b -> a was a border edge: no longer
        const auto drop = [](std::vector<Side>& sides, int other) {
          const auto found = std::find_if(sides.begin(), sides.end(),
                                          [&](const Side& side) { return side.other == other; });
          if (found != sides.end()) sides.erase(found);
        };
        drop(leaving[b], a);
        drop(arriving[a], b);
      } else {
        leaving[a].push_back({b, c});
        arriving[b].push_back({a, c});
      }
    }
  };
  // Whether x lies between u and w around v (within 0.2 radians of the arc between them).
  const auto angle = [&](int v, int a, int b) {
    const auto to_a = minus(samples[a], samples[v]), to_b = minus(samples[b], samples[v]);
    return std::atan2(std::sqrt(dot(cross(to_a, to_b), cross(to_a, to_b))), dot(to_a, to_b));
  };
  // (Both its angles with u and w below theirs: the far edge of a sliver fan just outside the
  // gap is not between.)
  const auto between = [&](int v, int u, int x, int w) {
    const double across = angle(v, u, w), to_u = angle(v, u, x), to_w = angle(v, x, w);
    return to_u < across && to_w < across && to_u + to_w < across + 0.2;
  };
  for (bool progress = true; progress;) {
    progress = false;
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
          if (u == w) continue;
          // u-w may be an edge already only as a border edge w -> u: the triangle closes a loop.
          const int u_w_uses = uses(u, w);
          if (u_w_uses > 1 || (u_w_uses == 1 && !third.count(directed_key(w, u)))) continue;
          // That would close u's own fan, not join two.
          if (fan_end(third, u, v, surface.size()) == w) continue;
          // Across a gap next to both: no other fan's border edge at v lies between them.
          bool gap = true;
          for (const auto* sides : {&arriving[v], &leaving[v]}) {
            for (const Side& other : *sides) {
              if (other.other != u && other.other != w && between(v, u, other.other, w))
                gap = false;
            }
          }
          if (!gap) continue;
          const auto to_u = minus(samples[u], samples[v]), to_w = minus(samples[w], samples[v]);
          const double lengths = std::sqrt(dot(to_u, to_u) * dot(to_w, to_w));
          if (!(lengths > 0)) continue;
          const double cosine = dot(to_u, to_w) / lengths;
          if (cosine <= best_cosine) continue;
          if (!closes_corner_facing_on(samples, u, v, w, in.apex, out.apex)) continue;
          if (not_to_add({w, v, u})) continue;
          best_cosine = cosine;
          best = {w, v, u};
        }
      }
      // A pair next to a triangle added this round waits for the next round, when the border
      // there is known again (a second-best pair now could be the wrong gap).
      if (best_cosine < -1 || touched[best[0]] || touched[best[2]]) continue;
      add(best);
      for (int x : best) touched[x] = 1;
      ++joined;
      progress = true;
    }
  }
  return joined;
}

namespace pinch_detail {

// A run of triangle indices in compressed rows.
struct Span {
  const int* first;
  const int* last;
};

// Whether `triangles` (all at v) make one fan: each pair of them joined by a chain of triangles
// sharing an edge at v, that is a vertex other than v. A quick test before the fans are built:
// most vertices are not pinched. (The few that are build their fans as before, whose order
// decides ties between fans: a partition found here would come in another order.) `around` is
// scratch space.
inline bool one_fan(const std::vector<Facet<3>>& surface, int v, const std::vector<int>& triangles,
                    std::vector<std::pair<int, int>>& around) {
  // (vertex other than v, triangle's place in `triangles`), sorted: triangles sharing a vertex
  // are adjacent in it. Their fans are merged by a union-find on places.
  around.clear();
  for (int i = 0; i < static_cast<int>(triangles.size()); ++i) {
    for (int u : surface[triangles[i]]) {
      if (u != v) around.push_back({u, i});
    }
  }
  std::sort(around.begin(), around.end());
  Union_find fans(triangles.size());
  std::size_t joins = 0;
  for (std::size_t j = 1; j < around.size(); ++j) {
    if (around[j].first == around[j - 1].first)
      joins += fans.unite(around[j].second, around[j - 1].second);
  }
  return joins + 1 == triangles.size();
}

}  // namespace pinch_detail

// Where fans stay pinched (folded against each other, or their gap's third edge inside the
// surface already), the fan on the largest piece of the surface is kept and the others go, each
// when every sample on it stays on some other triangle and no small piece of the surface is cut
// off by it (a search from each triangle left at the fan's other vertices, across edges,
// reaches far enough).
inline std::size_t drop_pinched_fans(std::vector<Facet<3>>& surface, std::size_t sample_count) {
  using pinch_detail::one_fan;
  using pinch_detail::Span;
  constexpr std::size_t small_piece = 64;  // triangles: fewer cut off is a piece of its own
  std::size_t dropped = 0;
  for (bool progress = true; progress;) {
    progress = false;
    // The triangles at each sample, in compressed rows (in the order of the triangles).
    std::vector<int> at_offsets(sample_count + 1, 0), at_triangles(3 * surface.size());
    for (const auto& t : surface) {
      for (int u : t) ++at_offsets[u + 1];
    }
    for (std::size_t u = 0; u < sample_count; ++u) at_offsets[u + 1] += at_offsets[u];
    {
      std::vector<int> fill(at_offsets.begin(), at_offsets.end() - 1);
      for (int t = 0; t < static_cast<int>(surface.size()); ++t) {
        for (int u : surface[t]) at_triangles[fill[u]++] = t;
      }
    }
    const auto at = [&](int sample) {
      return Span{at_triangles.data() + at_offsets[sample],
                  at_triangles.data() + at_offsets[sample + 1]};
    };
    // The triangles on each edge: (edge key, triangle) sorted by key; and for the edge j of
    // triangle t (slot 3 t + j), where the triangles on it start in that order.
    const auto key_of = [&](int t, int j) {
      return edge_key(surface[t][j], surface[t][(j + 1) % 3]);
    };
    std::vector<std::pair<std::uint64_t, int>> on_edge;
    on_edge.reserve(3 * surface.size());
    for (int t = 0; t < static_cast<int>(surface.size()); ++t) {
      for (int j = 0; j < 3; ++j) on_edge.push_back({key_of(t, j), t});
    }
    std::sort(on_edge.begin(), on_edge.end());
    std::vector<int> edge_first(3 * surface.size());
    for (std::size_t i = 0, first = 0; i < on_edge.size(); ++i) {
      if (on_edge[i].first != on_edge[first].first) first = i;
      const int t = on_edge[i].second;
      for (int j = 0; j < 3; ++j) {
        if (key_of(t, j) == on_edge[i].first) edge_first[3 * t + j] = static_cast<int>(first);
      }
    }
    std::vector<char> gone(surface.size(), 0);
    // The triangles at a sample not dropped yet.
    const auto triangles_left_at = [&](int sample) {
      const Span triangles = at(sample);
      return std::count_if(triangles.first, triangles.last, [&](int t) { return !gone[t]; });
    };
    // How many triangles are reached from `from` across edges, the gone ones left out, counting
    // up to `enough`.
    std::vector<int> seen_mark(surface.size(), -1), stack;
    int search = 0;
    const auto piece_from = [&](int from, std::size_t enough) {
      ++search;
      std::size_t reached = 0;
      stack.assign(1, from);
      seen_mark[from] = search;
      while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        if (++reached >= enough) return reached;
        for (int j = 0; j < 3; ++j) {
          const std::uint64_t key = on_edge[edge_first[3 * t + j]].first;
          for (auto it = on_edge.begin() + edge_first[3 * t + j];
               it != on_edge.end() && it->first == key; ++it) {
            const int u = it->second;
            if (gone[u] || seen_mark[u] == search) continue;
            seen_mark[u] = search;
            stack.push_back(u);
          }
        }
      }
      return reached;
    };
    std::vector<int> triangles;
    std::vector<std::pair<int, int>> around;
    for (int v = 0; v < static_cast<int>(sample_count); ++v) {
      // The fans at v: its triangles, joined where they share an edge at v.
      triangles.clear();
      for (const int* t = at(v).first; t != at(v).last; ++t) {
        if (!gone[*t]) triangles.push_back(*t);
      }
      if (triangles.size() < 2 || one_fan(surface, v, triangles, around)) continue;
      std::vector<int> fan_of(triangles.size());
      for (std::size_t i = 0; i < triangles.size(); ++i) fan_of[i] = static_cast<int>(i);
      const auto root = [&](int i) {
        while (fan_of[i] != i) i = fan_of[i] = fan_of[fan_of[i]];
        return i;
      };
      for (std::size_t i = 0; i < triangles.size(); ++i) {
        for (std::size_t j = i + 1; j < triangles.size(); ++j) {
          bool shared = false;
          for (int a : surface[triangles[i]]) {
            for (int b : surface[triangles[j]]) shared = shared || (a == b && a != v);
          }
          if (shared) fan_of[root(static_cast<int>(i))] = root(static_cast<int>(j));
        }
      }
      std::map<int, std::vector<int>> fans;  // by root: ordered, the same run to run
      for (std::size_t i = 0; i < triangles.size(); ++i)
        fans[root(static_cast<int>(i))].push_back(triangles[i]);
      if (fans.size() < 2) continue;
      // The fan kept is the one on the largest piece (a flap with more triangles at v than the
      // sheet it hangs from is not kept in the sheet's place).
      constexpr std::size_t large_piece = 4 * small_piece;
      auto largest = fans.begin();
      std::size_t largest_piece = 0;
      for (auto it = fans.begin(); it != fans.end(); ++it) {
        const std::size_t piece = piece_from(it->second.front(), large_piece);
        if (piece > largest_piece ||
            (piece == largest_piece && it->second.size() > largest->second.size())) {
          largest = it;
          largest_piece = piece;
        }
      }
      for (auto it = fans.begin(); it != fans.end(); ++it) {
        if (it == largest) continue;
        std::map<int, int> on_fan;  // sample -> triangles of the fan it is on
        for (int t : it->second) {
          for (int u : surface[t]) ++on_fan[u];
        }
        bool stays = true;
        for (const auto& [u, count] : on_fan) stays = stays && triangles_left_at(u) > count;
        if (!stays) continue;
        for (int t : it->second) gone[t] = 1;
        bool cuts = false;
        for (const auto& [u, count] : on_fan) {
          if (u == v) continue;
          for (const int* t = at(u).first; t != at(u).last; ++t) {
            cuts = cuts || (!gone[*t] && piece_from(*t, small_piece) < small_piece);
          }
        }
        if (cuts) {
          for (int t : it->second) gone[t] = 0;
          continue;
        }
        ++dropped;
        progress = true;
      }
    }
    std::vector<Facet<3>> kept;
    for (std::size_t t = 0; t < surface.size(); ++t) {
      if (!gone[t]) kept.push_back(surface[t]);
    }
    surface.swap(kept);
  }
  return dropped;
}

}  // namespace sculpt
