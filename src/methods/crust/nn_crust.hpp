// SPDX-License-Identifier: GPL-3.0-or-later
// The nearest-neighbour crust of Dey and Kumar (1999), for plane curves:
//   for each sample s:
//       q <- the nearest sample to s                  (always a Delaunay neighbour)
//       r <- the nearest sample to s at more than 90 degrees from q, seen from s
//       keep sq and sr
// On a closed curve sampled densely enough (epsilon < 1/3) the kept edges are exactly the
// polygon through consecutive samples. The method reads the first triangulation (stage 1) and
// nothing else; the robust method's open curves (src/methods/robust/open_curves.hpp) start from
// the same edges.
#pragma once

#include <cmath>
#include <sculpt/sculpt.hpp>
#include <set>
#include <utility>
#include <vector>

#include "../../core/stage_clock.hpp"

namespace sculpt {

struct Neighbour_edges {
  struct Edge {
    int sample, neighbour;
    double length;
    bool nearest;  // sq (true) or the far-side sr (false)
  };
  std::vector<Edge> edges;      // two a sample at most: sq, then sr if s has one
  std::vector<double> spacing;  // per sample: the distance to its nearest neighbour
};

namespace nn_crust_detail {

inline double distance(const Point<2>& a, const Point<2>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

}  // namespace nn_crust_detail

// The NN-crust's edges among the first n sites (the samples) of a 2D Delaunay triangulation
// whose vertices carry their site index; the other sites (box corners) are ignored.
template <class Triangulation>
Neighbour_edges nn_crust_edges(const Triangulation& triangulation,
                               const std::vector<Point<2>>& sites, int n) {
  using nn_crust_detail::distance;
  std::vector<std::vector<int>> neighbours(n);
  for (auto edge = triangulation.finite_edges_begin(); edge != triangulation.finite_edges_end();
       ++edge) {
    const auto& [face, i] = *edge;
    const int a = face->vertex(face->cw(i))->info(), b = face->vertex(face->ccw(i))->info();
    if (a >= n || b >= n) continue;
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  Neighbour_edges result;
  result.spacing.assign(n, HUGE_VAL);
  for (int s = 0; s < n; ++s) {
    int q = -1;
    for (int candidate : neighbours[s]) {
      if (const double d = distance(sites[s], sites[candidate]); d < result.spacing[s]) {
        result.spacing[s] = d;
        q = candidate;
      }
    }
    if (q < 0) continue;
    result.edges.push_back({s, q, result.spacing[s], true});
    int r = -1;
    double best = HUGE_VAL;
    for (int candidate : neighbours[s]) {
      const double dot = (sites[candidate][0] - sites[s][0]) * (sites[q][0] - sites[s][0]) +
                         (sites[candidate][1] - sites[s][1]) * (sites[q][1] - sites[s][1]);
      if (dot >= 0) continue;
      if (const double d = distance(sites[s], sites[candidate]); d < best) {
        best = d;
        r = candidate;
      }
    }
    if (r >= 0) result.edges.push_back({s, r, best, false});
  }
  return result;
}

// Edges given as neighbour lists, as polylines: each piece walked from one of its ends (or
// anywhere on a loop), so consecutive edges share a vertex and run the same way. Edges at a
// branching sample are walked too, as further pieces.
inline std::vector<Facet<2>> chained_edges(const std::vector<std::vector<int>>& joined) {
  const int n = static_cast<int>(joined.size());
  std::vector<Facet<2>> facets;
  std::set<std::pair<int, int>> walked;
  const auto walk_from = [&](int start) {
    bool any = false;
    for (int at = start, moved = 1; moved;) {
      moved = 0;
      for (int next : joined[at]) {
        if (!walked.insert({std::min(at, next), std::max(at, next)}).second) continue;
        facets.push_back({at, next});
        at = next;
        moved = 1;
        any = true;
        break;
      }
    }
    return any;
  };
  for (int s = 0; s < n; ++s) {
    if (joined[s].size() == 1) walk_from(s);  // open curves first, from an end
  }
  for (int s = 0; s < n; ++s) {
    while (walk_from(s)) {
    }  // then loops, and the pieces left at branching samples
  }
  return facets;
}

// Edges as neighbour lists of n samples, each edge once.
inline std::vector<std::vector<int>> neighbour_lists(
    int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> joined(n);
  std::set<std::pair<int, int>> seen;
  for (const auto& [a, b] : edges) {
    if (!seen.insert({std::min(a, b), std::max(a, b)}).second) continue;
    joined[a].push_back(b);
    joined[b].push_back(a);
  }
  return joined;
}

template <class Traits>
void run_nn_crust_method(const typename Traits::Triangulation& triangulation,
                         Reconstruction<2>& result, Stage_clock& clock) {
  clock.start("surface");
  const int n = static_cast<int>(result.sample_count());
  std::vector<std::pair<int, int>> edges;
  for (const auto& edge : nn_crust_edges(triangulation, result.sites, n).edges) {
    edges.push_back({edge.sample, edge.neighbour});
  }
  result.surface = chained_edges(neighbour_lists(n, edges));
}

}  // namespace sculpt
