// SPDX-License-Identifier: GPL-3.0-or-later
// Outliers: samples that no surface through their neighbours passes near. A scanner's stray
// returns (a reflection, an edge seen at a grazing angle, dust) land off the surface, and a
// method that interpolates must pass through them: each becomes a spike, or a dent where it lies
// inside. The cleaning stage (driver/cleaning.hpp) removes them before any method.
//
// Each sample is judged against its 14 nearest others, by two tests, either of which is enough:
// - Far off their surface. A plane is fitted to the neighbours, then again to the 10 of them
//   nearest that first plane, so that another outlier among them does not tilt it. The sample is
//   an outlier when its height over that plane exceeds three times what the neighbours allow:
//   three times their own spread about the plane (noise, and curvature over the neighbourhood)
//   plus their spacing (the median of their mean distances to their three nearest). A sample on
//   a sharp edge or a corner stands over its neighbours' plane too, but by no more than they
//   spread about it.
// - Alone, and off. Its mean distance to its 14 nearest (its reach) is more than three times the
//   median of theirs, and it stands over the plane of those beyond a third of its reach by more
//   than they allow (once, not three times). A small cluster of outliers passes the first test
//   (its members fit a plane together, with their neighbours' help) but not this one: the
//   cluster's members are near, the surface's samples beyond, where they are close to one
//   another. A sample of the surface beside a patch scanned denser is alone too, but on the
//   patch's plane (a sphere of 3,000 samples with a patch 30 and 100 times denser: 13 and 26
//   alone, none off).
// The samples left are judged again, until none is found (at most four rounds): a stray among
// another's neighbours can hide it from the plane test, which finds it once the first is gone
// (3 of the 40 strays of tests/outliers_test.cpp's torus). A cluster of up to 7 strays is found
// (the test builds clusters of 2 to 12, 12 spacings off the torus); one of 8 or more, over half
// a neighbourhood, is a patch of its own and stays. Samples
// nearer one another than a millionth of the samples' box are judged as one: twenty returns at
// one spot would otherwise fill their neighbours' neighbourhoods, which then describe a point,
// not a surface.
//
// Both tests compare a sample with its own neighbours, so the sampling density may vary across
// the surface. What they cannot tell is a mesh's lone vertex far from denser ones (CGAL's
// boeing, oblong and mannequin-devil have dozens): a mesh's vertices are not a scan's samples,
// and removal is for scans, asked for (Cleaning::outliers) or done with the smoothing of noisy
// samples, never on clean samples by default. Nor is a stray found within about three spacings
// of the surface (to these tests it is noise; the smoothing moves it back), or inside a tube a
// few spacings round, whose wall surrounds it. On a torus of 4,000 samples with 40 strays 1 to
// 12 spacings away in random directions, the tests find the 23 farthest and no sample of the
// torus (tests/outliers_test.cpp measures more).
#pragma once

#include <algorithm>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "point_tree.hpp"
#include "sample_noise.hpp"
#include "without.hpp"

namespace sculpt {

inline constexpr int outlier_neighbours = 14;     // each sample's nearest others it is judged by
inline constexpr int outlier_plane_support = 10;  // the neighbours the second plane is fitted to
inline constexpr int spacing_neighbours = 3;      // a sample's spacing: to its 3 nearest others
inline constexpr double spread_allowed = 3;       // the neighbours' spread: 3 deviations of noise
inline constexpr double outlier_margin = 3;       // how many times what the neighbours allow
inline constexpr int outlier_rounds = 4;          // judged again among the samples left
inline constexpr double same_spot = 1e-6;         // of the box's diagonal: samples judged as one

namespace outlier_detail {

struct Plane {
  Point<3> centre, normal;
};

// The plane through the centroid of the points, normal to their direction of least spread.
inline Plane fitted_plane(const std::vector<Point<3>>& points) {
  Point<3> centre{0, 0, 0};
  for (const auto& p : points) {
    for (int k = 0; k < 3; ++k) centre[k] += p[k] / static_cast<double>(points.size());
  }
  double m[3][3] = {};
  for (const auto& p : points) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += (p[i] - centre[i]) * (p[j] - centre[j]);
    }
  }
  return {centre, eigenvector(m, eigenvalues(m)[0])};
}

inline double height(const Plane& plane, const Point<3>& p) {
  double h = 0;
  for (int k = 0; k < 3; ++k) h += (p[k] - plane.centre[k]) * plane.normal[k];
  return std::abs(h);
}

inline double distance(const Point<3>& a, const Point<3>& b) {
  double d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(d2);
}

inline double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// For each sample, the first sample at its spot (nearer than `tolerance`): itself, unless an
// earlier one lies there.
inline std::vector<int> first_at_spot(const std::vector<Point<3>>& samples, double tolerance) {
  const int n = static_cast<int>(samples.size());
  std::vector<int> first(n);
  for (int i = 0; i < n; ++i) first[i] = i;
  if (n < 2) return first;
  const Point_tree<3> tree(samples.data(), samples.data() + samples.size());
  const double tolerance2 = tolerance * tolerance;
  for (int i = 0; i < n; ++i) {
    tree.any_within_indexed(samples[i], tolerance2, [&](const Point<3>&, int j) {
      if (j < first[i]) first[i] = j;
      return false;  // look at every one
    });
    first[i] = first[first[i]];  // an earlier sample's first is settled already
  }
  return first;
}

// The outliers among samples at distinct spots, by the two tests at the top.
inline std::vector<int> outliers_among(const std::vector<Point<3>>& samples) {
  const int n = static_cast<int>(samples.size());
  constexpr int k = outlier_neighbours;
  if (n <= k) return {};
  const Point_tree<3> tree(samples.data(), samples.data() + samples.size());
  const std::vector<int> nearest = tree.k_nearest(k + 1);
  // Each sample's nearest others (itself left out wherever the tree put it).
  std::vector<int> neighbours(static_cast<std::size_t>(n) * k, -1);
  for (int i = 0; i < n; ++i) {
    int found = 0;
    for (int j = 0; j <= k && found < k; ++j) {
      const int other = nearest[std::size_t(i) * (k + 1) + j];
      if (other >= 0 && other != i) neighbours[std::size_t(i) * k + found++] = other;
    }
  }
  const auto neighbour = [&](int i, int j) { return neighbours[std::size_t(i) * k + j]; };
  std::vector<double> spacing(n, 0), reach(n, 0);  // mean distance to the 3 and the k nearest
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j) {
      const double d = distance(samples[i], samples[neighbour(i, j)]);
      if (j < spacing_neighbours) spacing[i] += d / spacing_neighbours;
      reach[i] += d / k;
    }
  }
  std::vector<int> outliers;
  std::vector<Point<3>> around(k), support(outlier_plane_support);
  std::vector<double> their_spacing(k), their_reach(k);
  std::vector<std::pair<double, int>> by_height(k);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j) {
      around[j] = samples[neighbour(i, j)];
      their_spacing[j] = spacing[neighbour(i, j)];
      their_reach[j] = reach[neighbour(i, j)];
    }
    const Plane first = fitted_plane(around);
    for (int j = 0; j < k; ++j) by_height[j] = {height(first, around[j]), j};
    std::sort(by_height.begin(), by_height.end());
    for (int j = 0; j < outlier_plane_support; ++j) support[j] = around[by_height[j].second];
    const Plane plane = fitted_plane(support);
    double spread = 0;
    for (const auto& p : support) spread += height(plane, p) * height(plane, p);
    spread = std::sqrt(spread / outlier_plane_support);
    const double allowed = spread_allowed * spread + median(their_spacing);
    const bool off = height(plane, samples[i]) > outlier_margin * allowed;
    bool alone = false;
    if (!off && reach[i] > outlier_margin * median(their_reach)) {
      // Off the plane of the neighbours beyond a third of its reach: a cluster's other members
      // are nearer, the surface around it farther.
      std::vector<Point<3>> beyond;
      for (int j = 0; j < k; ++j) {
        if (distance(samples[i], around[j]) > reach[i] / 3) beyond.push_back(around[j]);
      }
      if (beyond.size() < 3) beyond = around;
      const Plane far = fitted_plane(beyond);
      double far_spread = 0;
      for (const auto& p : beyond) far_spread += height(far, p) * height(far, p);
      far_spread = std::sqrt(far_spread / static_cast<double>(beyond.size()));
      alone = height(far, samples[i]) > spread_allowed * far_spread + median(their_spacing);
    }
    if (off || alone) outliers.push_back(i);
  }
  return outliers;
}

}  // namespace outlier_detail

// The indices of the outliers among the samples, increasing (see the top). None among fewer
// samples than a neighbourhood holds.
inline std::vector<int> outlying_samples(const std::vector<Point<3>>& samples) {
  using namespace outlier_detail;
  if (samples.empty()) return {};
  Point<3> lo = samples.front(), hi = samples.front();
  for (const auto& p : samples) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const std::vector<int> first = first_at_spot(samples, same_spot * distance(lo, hi));
  // The samples judged: one per spot, each standing for those at its spot.
  std::vector<int> judged;
  for (int i = 0; i < static_cast<int>(samples.size()); ++i) {
    if (first[i] == i) judged.push_back(i);
  }
  std::vector<char> outlier(samples.size(), 0);
  for (int round = 0; round < outlier_rounds; ++round) {
    std::vector<Point<3>> left;
    left.reserve(judged.size());
    for (int i : judged) left.push_back(samples[i]);
    const std::vector<int> found = outliers_among(left);
    if (found.empty()) break;
    for (int f : found) outlier[judged[f]] = 1;
    judged = without(judged, found);
  }
  std::vector<int> outliers;
  for (int i = 0; i < static_cast<int>(samples.size()); ++i) {
    if (outlier[first[i]]) outliers.push_back(i);
  }
  return outliers;
}

}  // namespace sculpt
