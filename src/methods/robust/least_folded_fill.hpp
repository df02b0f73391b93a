// SPDX-License-Identifier: GPL-3.0-or-later
// The triangulation of a border loop that folds least: of all triangulations of the loop, one
// whose sharpest fold (between two adjacent triangles of it, or one of it and the surface's
// triangle on a loop edge) is the least sharp, folds within 1e-9 of each other counting as the
// same and going to the smaller area where a sub-chain chooses. Liepa ("Filling holes in
// meshes", SGP 2003) weighs a hole's fills the same way, by dynamic programming over the loop's
// sub-chains; here the programme keeps the triangle across each sub-chain's base as part of the
// problem, so the sharpest fold found is the best of all triangulations, at O(k^4) for a loop
// of k samples (k <= 64: about 1.3M steps and 1.7 MB at most).
//
// Greedy ear clipping decides each ear from the ears before it and cannot see the last one: on a
// sheet with noise of 2% of its spacing it closed a 15-sample gap with a last triangle turned
// 174° from its neighbours, and refused gaps whose every fill folds a little.
//
// A sub-chain v_i .. v_j (i < j) is triangulated on its base v_i v_j by a top triangle
// (v_j, v_m, v_i), i < m < j, facing as the fill does (against the loop's direction). How
// sharply it folds depends on the triangle across its base, so
//
//   within(i, j, m)     = the best fold of sub-chain i..j with top triangle m, not counting its
//                         base: the worse of beside(i, m, t) and beside(m, j, t), t its top
//   beside(i, j, n)     = the best, over the top triangles m of sub-chain i..j, of the worse of
//                         within(i, j, m) and the fold between m's triangle and the normal n across
//                         its base; for j = i + 1 (a loop edge) the fold between the surface's
//                         triangle on it and n
//   fill                = the best top triangle m of the whole loop 0..k-1, whose base v_0 v_{k-1}
//                         is a loop edge: the worse of within(0, k-1, m) and its fold there
//
// A diagonal the surface already has as an edge would be used three times: no sub-chain stands
// on it. A degenerate triangle has no normal: it is never used. A loop that passes a sample
// twice, or beside a degenerate triangle of the surface (no normal to fold against), gets no
// fill.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../extraction/manifold_extraction.hpp"
#include "../extraction/vector3.hpp"
#include "border_edges.hpp"

namespace sculpt {

struct Loop_fill {
  std::vector<Facet<3>> triangles;  // empty: the loop cannot be triangulated
  // The cosine of the angle between the normals at the sharpest fold: 1 flat, < 0 folded by
  // more than a right angle.
  double sharpest_fold_cos = -2;
};

namespace fill_detail {

// How good a (partial) fill is: the cosine at its sharpest fold (larger is better), then its
// doubled area (smaller is better). Folds within a rounding of each other tie.
struct Quality {
  double fold = -3;  // -3: no fill
  double area = 0;
  bool exists() const { return fold > -2.5; }
  bool better_than(const Quality& other) const {
    constexpr double same_fold = 1e-9;
    if (!other.exists()) return exists();
    return fold > other.fold + same_fold || (fold > other.fold - same_fold && area < other.area);
  }
};

inline Quality worse_of(const Quality& a, const Quality& b) {
  return {std::min(a.fold, b.fold), a.area + b.area};
}

}  // namespace fill_detail

// `loop`: the loop's samples in the direction of the surface's triangles' own edges;
// `edge_normals[i]`: the normal of the surface's triangle on the edge loop[i] -> loop[i + 1].
inline Loop_fill least_folded_fill(const std::vector<Point<3>>& samples,
                                   const std::vector<int>& loop,
                                   const std::vector<extraction_detail::Vector>& edge_normals,
                                   const Edge_uses& edges) {
  using extraction_detail::dot;
  using extraction_detail::normal_of;
  using extraction_detail::Vector;
  using fill_detail::Quality;
  const int k = static_cast<int>(loop.size());
  if (k < 3 || edge_normals.size() != loop.size()) return {};
  std::vector<int> distinct = loop;
  std::sort(distinct.begin(), distinct.end());
  if (std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end()) return {};
  const auto unit = [](Vector v) {
    const double length = std::sqrt(dot(v, v));
    for (double& x : v) x /= length;
    return v;
  };
  std::vector<Vector> unit_edge_normals;
  for (const auto& n : edge_normals) {
    if (!(dot(n, n) > 0)) return {};
    unit_edge_normals.push_back(unit(n));
  }
  // The top triangles (v_j, v_m, v_i) of sub-chain i..j, m = i+1 .. j-1, are filed from
  // first[i * k + j] on: k (k-1) (k-2) / 6 of them in all.
  std::vector<std::size_t> first(static_cast<std::size_t>(k) * k, 0);
  std::size_t triangles = 0;
  for (int i = 0; i < k; ++i) {
    for (int j = i + 2; j < k; ++j) {
      first[static_cast<std::size_t>(i) * k + j] = triangles;
      triangles += j - i - 1;
    }
  }
  const auto index = [&](int i, int m, int j) {
    return first[static_cast<std::size_t>(i) * k + j] + (m - i - 1);
  };
  // Each top triangle's unit normal, and within(i, j, m) (which counts its area).
  std::vector<Vector> normal(triangles);
  std::vector<Quality> within(triangles);
  const auto may_stand_on = [&](int i, int j) {
    return (i == 0 && j == k - 1) || !edges.count(edge_key(loop[i], loop[j]));
  };
  // beside(i, j, n), and the top triangle that gives it (-1 for a loop edge or none).
  const auto beside = [&](int i, int j, const Vector& across, int* top = nullptr) {
    if (top) *top = -1;
    if (j == i + 1) return Quality{dot(unit_edge_normals[i], across), 0.0};
    Quality best;
    for (int m = i + 1; m < j; ++m) {
      const std::size_t t = index(i, m, j);
      if (!within[t].exists()) continue;
      const Quality here = worse_of(within[t], {dot(normal[t], across), 0.0});
      if (here.better_than(best)) {
        best = here;
        if (top) *top = m;
      }
    }
    return best;
  };
  for (int span = 2; span < k; ++span) {
    for (int i = 0; i + span < k; ++i) {
      const int j = i + span;
      if (!may_stand_on(i, j)) continue;
      for (int m = i + 1; m < j; ++m) {
        const std::size_t t = index(i, m, j);
        const Vector n = normal_of(samples, loop[j], loop[m], loop[i]);
        const double doubled_area = std::sqrt(dot(n, n));
        if (!(doubled_area > 0)) continue;
        normal[t] = unit(n);
        const Quality left = beside(i, m, normal[t]), right = beside(m, j, normal[t]);
        if (!left.exists() || !right.exists()) continue;
        within[t] = worse_of(worse_of(left, right), {1.0, doubled_area});
      }
    }
  }
  // The whole loop: its base v_0 v_{k-1} is the loop edge k-1.
  int top = -1;
  const Quality whole = beside(0, k - 1, unit_edge_normals[k - 1], &top);
  if (!whole.exists()) return {};
  Loop_fill fill;
  fill.sharpest_fold_cos = whole.fold;
  // Down from the top: each sub-chain's top triangle is the best beside its parent's.
  struct Chain {
    int i, j, m;
  };
  std::vector<Chain> chains = {{0, k - 1, top}};
  while (!chains.empty()) {
    const auto [i, j, m] = chains.back();
    chains.pop_back();
    fill.triangles.push_back({loop[j], loop[m], loop[i]});
    const Vector& n = normal[index(i, m, j)];
    for (const auto& [a, b] : {std::pair{i, m}, std::pair{m, j}}) {
      int below = -1;
      beside(a, b, n, &below);
      if (below >= 0) chains.push_back({a, b, below});
    }
  }
  return fill;
}

}  // namespace sculpt
