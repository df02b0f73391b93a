// SPDX-License-Identifier: GPL-3.0-or-later
// Undersampling detection for the co-cone (Dey & Giesen 2001, "Detecting undersampling in
// surface reconstruction"; the boundary co-cone of Dey's book, 2007, sec. 5.2): where the
// samples are dense enough, a sample's Voronoi cell is long and thin along the normal, and its
// neighbours' pole vectors agree with its own. Where they are not (a border, a sharp edge, a
// thin part sampled too sparsely), the cell is fat or the normals disagree, and the co-cone's
// rule there would choose wrong triangles. Such samples are marked and impose no co-cone: the
// surface gets a hole there instead of a defect (the "modified co-cone" of Kuo & Yau, Fig. 15b).
//
//   r(p) <- the farthest point of Vor(p) in the plane through p normal to v(p) = p+ - p
//           (the Voronoi edges of p that cross the plane: its width)
//   h(p) <- the distance to the nearer pole (its height)
//   R <- { p : r(p) <= ρ h(p), and v(q) within θ of ±v(p) for every co-cone neighbour q }
//   grow R: add p with r(p) <= ρ h(p) and one co-cone neighbour q in R within θ, repeatedly
//   the undersampled samples: those not in R
// ρ = 1/1.2 and θ = π/3, the constants of Dey and Goswami's Tight Cocone program (the paper
// leaves them to the implementation); a co-cone neighbour q of p shares with p a Delaunay
// triangle whose Voronoi edge meets the co-cone of p. The ratio is lenient: on CGAL's knot1 and
// bunny00, which every method closes, it reaches 0.46 and 0.66, and at the rim of an opening
// in a unit sphere about the opening's radius; so only openings wider than the local feature
// size are found (a sphere cut at z = 0.3, not one cut at z = 0.7, which the co-cone closes).
#pragma once

#include <cmath>
#include <deque>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../extraction/manifold_extraction.hpp"

namespace sculpt {

// The width-to-height ratio below which a Voronoi cell counts as long and thin.
inline constexpr double thin_cell_ratio = 1 / 1.2;
// Neighbours' normals (unoriented) agree within this angle.
inline constexpr double normal_agreement_angle = M_PI / 3;

// A Delaunay triangle between samples whose Voronoi edge meets the co-cone of at least one of its
// vertices (which, for each vertex): the co-cone's candidates, and its neighbour relation. The
// others are never chosen and make no neighbours, so they are not kept (16 bytes a triangle,
// where keeping every triangle with its Voronoi edge took 64: bunny00 subdivided, 2.1M of them).
struct Cocone_triangle {
  Facet<3> samples;
  std::array<bool, 3> meets_cocone;
};

// The width r(p) of each sample's Voronoi cell, grown one Voronoi edge at a time: where the edge
// from `from` to `to`, dual to a triangle of the samples in `samples`, crosses the plane through
// each of them normal to its v(p). `width` starts at 0 for every sample.
inline void widen_by_voronoi_edge(const Reconstruction<3>& result,
                                  const std::vector<std::array<double, 3>>& normals,
                                  const Facet<3>& samples, const Point<3>& from, const Point<3>& to,
                                  std::vector<double>& width) {
  using namespace extraction_detail;
  for (int j = 0; j < 3; ++j) {
    const int p = samples[j];
    const Point<3>& at = result.sites[p];
    const double a = dot(minus(from, at), normals[p]);
    const double b = dot(minus(to, at), normals[p]);
    if ((a > 0) == (b > 0) || a == b) continue;  // on one side of the plane
    const double s = a / (a - b);
    Point<3> crossing;
    for (int k = 0; k < 3; ++k) crossing[k] = from[k] + s * (to[k] - from[k]);
    const Vector d = minus(crossing, at);
    width[p] = std::max(width[p], std::sqrt(dot(d, d)));
  }
}

// Returns, per sample, whether it is undersampled, from the widths of the Voronoi cells
// (widen_by_voronoi_edge over every Voronoi edge dual to a triangle of samples) and the triangles
// whose Voronoi edge meets a co-cone.
inline std::vector<bool> undersampled_samples(const Reconstruction<3>& result,
                                              const std::vector<std::array<double, 3>>& normals,
                                              const std::vector<double>& width,
                                              const std::vector<Cocone_triangle>& triangles) {
  using namespace extraction_detail;
  const int n = static_cast<int>(result.sample_count());
  const auto& stage = result.poles;

  std::vector<bool> thin(n, false);
  for (int p = 0; p < n; ++p) {
    double height = INFINITY;
    for (int pole : {stage.positive_pole[p], stage.negative_pole[p]}) {
      if (pole >= 0) height = std::min(height, stage.poles[pole].radius);
    }
    thin[p] = std::isfinite(height) && width[p] <= thin_cell_ratio * height;
  }

  // Co-cone neighbours in compressed rows: q in the row of p when q is a co-cone neighbour of
  // p, and p in the row of q of the reverse relation (it is not symmetric).
  const auto rows = [&](bool reverse) {
    // Named references, not a structured binding: C++17 lambdas cannot capture bindings.
    std::pair<std::vector<int>, std::vector<int>> row_set;
    std::vector<int>& offsets = row_set.first;
    std::vector<int>& entries = row_set.second;
    offsets.assign(n + 1, 0);
    const auto for_each_pair = [&](auto&& use) {
      for (const auto& t : triangles) {
        for (int j = 0; j < 3; ++j) {
          if (!t.meets_cocone[j]) continue;
          for (int other : {t.samples[(j + 1) % 3], t.samples[(j + 2) % 3]}) {
            reverse ? use(other, t.samples[j]) : use(t.samples[j], other);
          }
        }
      }
    };
    for_each_pair([&](int p, int) { ++offsets[p + 1]; });
    for (int p = 0; p < n; ++p) offsets[p + 1] += offsets[p];
    entries.resize(offsets[n]);
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for_each_pair([&](int p, int q) { entries[fill[p]++] = q; });
    return row_set;
  };
  const auto [offsets, neighbours] = rows(false);
  const auto [reverse_offsets, neighbour_of] = rows(true);
  static const double agreement = std::cos(normal_agreement_angle);
  const auto agree = [&](int p, int q) {
    return std::abs(dot(normals[p], normals[q])) >= agreement;
  };

  std::vector<bool> well_sampled(n, false);
  std::deque<int> grown;
  for (int p = 0; p < n; ++p) {
    if (!thin[p]) continue;
    bool all_agree = true;
    for (int i = offsets[p]; i < offsets[p + 1] && all_agree; ++i) {
      all_agree = agree(p, neighbours[i]);
    }
    if (all_agree) {
      well_sampled[p] = true;
      grown.push_back(p);
    }
  }
  // Grow R: when q joins, every thin p that has q as a co-cone neighbour and agrees with it.
  while (!grown.empty()) {
    const int q = grown.front();
    grown.pop_front();
    for (int i = reverse_offsets[q]; i < reverse_offsets[q + 1]; ++i) {
      const int p = neighbour_of[i];
      if (well_sampled[p] || !thin[p] || !agree(p, q)) continue;
      well_sampled[p] = true;
      grown.push_back(p);
    }
  }
  std::vector<bool> undersampled(n);
  for (int p = 0; p < n; ++p) undersampled[p] = !well_sampled[p];
  return undersampled;
}

}  // namespace sculpt
