// Plane curves that may end: the robust method's bordered rule in 2D (the paper's section 4 asks
// for reconstruction "with or without boundaries").
//
// Each sample joins its nearest neighbour, and its nearest neighbour on the far side of that
// one: the NN-crust of Dey and Kumar (1999), exact on closed curves sampled densely enough, and
// made of Delaunay edges only. Where a curve ends, the far-side neighbour of its last sample
// is a sample across the opening (the other end of an arc, the next turn of a spiral, another
// stroke), much farther away than the samples' spacing there. That edge is dropped when it is
// longer than `end_gap_ratio` times the larger spacing of its two ends, the spacing of a sample
// being the distance to its nearest neighbour. The edges are then taken shortest first, at most
// two a sample, so a curve never branches: where the sampling is too sparse for NN-crust, a
// curve ends instead. The result interpolates the samples; the closed robust rule (the carve)
// remains the better choice for closed curves sampled sparsely or with sharp corners.
#pragma once

#include <algorithm>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <set>
#include <utility>
#include <vector>

namespace sculpt {

// Along a curve sampled densely enough for the closed curves to come out exact, an edge is about
// as long as the spacing at its ends; across an opening the far-side neighbour lies many
// spacings away. Measured on the generated curves (tests/open_curves_test.cpp prints it): an
// edge along a curve is at most 1.0 times the larger spacing of its ends, an opening at least
// 5 (the spiral's arms, five spacings apart). 2.5 lies between, near their geometric mean, with
// room for uneven sampling on both sides.
constexpr double end_gap_ratio = 2.5;

namespace open_curves_detail {

inline double distance(const Point<2>& a, const Point<2>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// The edges as polylines: each piece walked from one of its ends (or anywhere on a loop), so
// consecutive edges share a vertex and run the same way.
inline std::vector<Facet<2>> chained(const std::vector<std::vector<int>>& joined) {
  const int n = static_cast<int>(joined.size());
  std::vector<Facet<2>> facets;
  std::set<std::pair<int, int>> walked;
  const auto walk_from = [&](int start) {
    int at = start;
    for (bool moved = true; moved;) {
      moved = false;
      for (int next : joined[at]) {
        if (!walked.insert({std::min(at, next), std::max(at, next)}).second) continue;
        facets.push_back({at, next});
        at = next;
        moved = true;
        break;
      }
    }
  };
  for (int s = 0; s < n; ++s) {
    if (joined[s].size() == 1) walk_from(s);  // open curves first, from an end
  }
  for (int s = 0; s < n; ++s) walk_from(s);  // then what is left: loops (and any branch)
  return facets;
}

}  // namespace open_curves_detail

// The curves through the first n sites (the samples) of a 2D Delaunay triangulation whose
// vertices carry their site index; the other sites (box corners) are ignored.
template <class Triangulation>
std::vector<Facet<2>> open_curves(const Triangulation& triangulation,
                                  const std::vector<Point<2>>& sites, int n) {
  using open_curves_detail::distance;
  std::vector<std::vector<int>> neighbours(n);
  for (auto edge = triangulation.finite_edges_begin(); edge != triangulation.finite_edges_end();
       ++edge) {
    const auto& [face, i] = *edge;
    const int a = face->vertex(face->cw(i))->info(), b = face->vertex(face->ccw(i))->info();
    if (a >= n || b >= n) continue;
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  // The nearest neighbour, always a Delaunay neighbour, and the spacing it gives.
  std::vector<int> nearest(n, -1);
  std::vector<double> spacing(n, 0.0);
  for (int p = 0; p < n; ++p) {
    double best = HUGE_VAL;
    for (int q : neighbours[p]) {
      if (const double d = distance(sites[p], sites[q]); d < best) {
        best = d;
        nearest[p] = q;
      }
    }
    spacing[p] = best;
  }
  // The candidates: every nearest-neighbour edge, and every far-side edge short enough.
  std::vector<std::pair<double, std::pair<int, int>>> candidates;
  const auto offer = [&](int a, int b) {
    candidates.push_back({distance(sites[a], sites[b]), {std::min(a, b), std::max(a, b)}});
  };
  for (int p = 0; p < n; ++p) {
    const int q = nearest[p];
    if (q < 0) continue;
    offer(p, q);
    // The nearest Delaunay neighbour at more than 90 degrees from q, seen from p.
    int far = -1;
    double best = HUGE_VAL;
    for (int r : neighbours[p]) {
      const double dot = (sites[r][0] - sites[p][0]) * (sites[q][0] - sites[p][0]) +
                         (sites[r][1] - sites[p][1]) * (sites[q][1] - sites[p][1]);
      if (dot >= 0) continue;
      if (const double d = distance(sites[p], sites[r]); d < best) {
        best = d;
        far = r;
      }
    }
    if (far >= 0 && best <= end_gap_ratio * std::max(spacing[p], spacing[far])) offer(p, far);
  }
  // Shortest first, at most two edges a sample: a curve never branches. On a curve sampled
  // densely enough every candidate is taken (NN-crust has no branch there); where it is not,
  // the longer of competing edges gives way and the curve ends instead of branching.
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::vector<int>> joined(n);
  for (const auto& [length, edge] : candidates) {
    const auto [a, b] = edge;
    if (joined[a].size() >= 2 || joined[b].size() >= 2) continue;
    if (std::find(joined[a].begin(), joined[a].end(), b) != joined[a].end()) continue;
    joined[a].push_back(b);
    joined[b].push_back(a);
  }
  return open_curves_detail::chained(joined);
}

}  // namespace sculpt
