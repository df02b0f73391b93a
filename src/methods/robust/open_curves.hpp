// SPDX-License-Identifier: GPL-3.0-or-later
// Plane curves that may end: the robust method's bordered rule in 2D (the paper's section 4 asks
// for reconstruction "with or without boundaries").
//
// It starts from the edges of the NN-crust (src/methods/crust/nn_crust.hpp): each sample's
// nearest neighbour and its nearest neighbour on the far side of that one. Where a curve ends,
// the far-side neighbour of its last sample is a sample across the opening (the other end of an
// arc, the next turn of a spiral, another stroke), much farther away than the samples' spacing
// there. That edge is dropped when it is longer than `end_gap_ratio` times the larger spacing
// of its two ends, the spacing of a sample being the distance to its nearest neighbour. The
// edges are then taken shortest first, at most two a sample, so a curve never branches, and no
// loop of fewer than `smallest_loop` samples closes: where the sampling is too sparse for the
// NN-crust, a curve ends instead. The result interpolates
// the samples; the closed rule (the carve) remains the better choice for closed curves sampled
// sparsely or with sharp corners.
#pragma once

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <tuple>
#include <utility>
#include <vector>

#include "../crust/nn_crust.hpp"

namespace sculpt {

// Along a curve sampled densely enough for the closed curves to come out exact, an edge is about
// as long as the spacing at its ends; across an opening the far-side neighbour lies many
// spacings away. Measured on the generated curves (tests/open_curves_test.cpp prints it): an
// edge along a curve is at most 1.0 times the larger spacing of its ends, an opening at least
// 5 (the spiral's arms, five spacings apart). 2.5 lies between, near their geometric mean, with
// room for uneven sampling on both sides.
constexpr double end_gap_ratio = 2.5;

// A closed curve sampled densely enough for any of these rules (epsilon < 1/3: each edge shorter
// than a third of the distance to the medial axis) has at least 2 pi / (1/3), about 19, samples:
// a smaller loop is an artefact of noise or sparse sampling (three samples closing a
// triangle), and its closing edge is refused, leaving the stroke open there. 6 stays well
// below any loop that can be sampled well.
constexpr int smallest_loop = 6;

// The curves through the first n sites (the samples) of a 2D Delaunay triangulation whose
// vertices carry their site index; the other sites (box corners) are ignored.
template <class Triangulation>
std::vector<Facet<2>> open_curves(const Triangulation& triangulation,
                                  const std::vector<Point<2>>& sites, int n) {
  const Neighbour_edges found = nn_crust_edges(triangulation, sites, n);
  std::vector<std::tuple<double, int, int>> offered;
  for (const auto& edge : found.edges) {
    const double spacing = std::max(found.spacing[edge.sample], found.spacing[edge.neighbour]);
    if (edge.nearest || edge.length <= end_gap_ratio * spacing) {
      offered.push_back({edge.length, std::min(edge.sample, edge.neighbour),
                         std::max(edge.sample, edge.neighbour)});
    }
  }
  // Shortest first, at most two edges a sample: a curve never branches. On a curve sampled
  // densely enough every offer is taken (the NN-crust has no branch there); where it is not,
  // the longer of competing edges gives way and the curve ends instead of branching.
  std::sort(offered.begin(), offered.end());
  std::vector<std::vector<int>> joined(n);
  // The pieces so far (every piece is a path until it closes): a union-find with sizes.
  std::vector<int> piece(n), size(n, 1);
  for (int s = 0; s < n; ++s) piece[s] = s;
  const auto find = [&](int s) {
    while (piece[s] != s) s = piece[s] = piece[piece[s]];
    return s;
  };
  for (const auto& [length, a, b] : offered) {
    if (joined[a].size() >= 2 || joined[b].size() >= 2) continue;
    if (std::find(joined[a].begin(), joined[a].end(), b) != joined[a].end()) continue;
    const int piece_a = find(a), piece_b = find(b);
    if (piece_a == piece_b && size[piece_a] < smallest_loop) continue;  // a tiny loop
    joined[a].push_back(b);
    joined[b].push_back(a);
    if (piece_a != piece_b) {
      piece[piece_b] = piece_a;
      size[piece_a] += size[piece_b];
    }
  }
  return chained_edges(joined);
}

}  // namespace sculpt
