// SPDX-License-Identifier: GPL-3.0-or-later
// Extreme but finite scales (a sphere of radius 1e80 or 1e-105, denormal coordinates) overflow
// or underflow the squared distances and circumradii every stage computes in floating point,
// and a small object far from the origin loses the digits its circumcentres need. So the
// stages run on normalised samples: translated (only when the cloud is far from the origin,
// and then by a multiple of a power of two no smaller than its extent, which makes every
// subtraction exact) and scaled by a power of two (exact) so that the longest side of the
// bounding box lies in [1, 2). Every predicate therefore decides as it would on the input; the
// samples are handed back as given and the other stored stages are mapped back at the end.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "point_names.hpp"

namespace sculpt {

template <int D>
struct Normalisation {
  Point<D> offset{};  // subtracted first
  int exponent = 0;   // then multiplied by 2^exponent

  bool identity() const {
    return exponent == 0 &&
           std::all_of(offset.begin(), offset.end(), [](double c) { return c == 0; });
  }
  Point<D> apply(Point<D> p) const {
    for (int k = 0; k < D; ++k) p[k] = std::ldexp(p[k] - offset[k], exponent);
    return p;
  }
  Point<D> undo(Point<D> p) const {
    for (int k = 0; k < D; ++k) p[k] = std::ldexp(p[k], -exponent) + offset[k];
    return p;
  }
};

// Coordinates this much smaller than the extent (after normalisation) would underflow the
// squared distances of the cells around them.
constexpr int smallest_normalised_exponent = -400;

template <int D>
Normalisation<D> normalisation_of(const std::vector<Point<D>>& samples) {
  Normalisation<D> result;
  if (samples.empty()) return result;
  Point<D> lo = samples[0], hi = samples[0];
  for (const auto& p : samples) {
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  // E: every side of the bounding box is below 2^E. A side is hi - lo (exact for denormals);
  // where that overflows (huge coordinates of both signs), twice the difference of halves.
  int E = std::numeric_limits<int>::min();
  for (int k = 0; k < D; ++k) {
    const double side = hi[k] - lo[k];
    int e = 0;
    if (std::isfinite(side)) {
      if (side == 0) continue;
      std::frexp(side, &e);  // side = m 2^e with m in [0.5, 1)
    } else {
      std::frexp(0.5 * hi[k] - 0.5 * lo[k], &e);
      e += 1;
    }
    E = std::max(E, e);
  }
  if (E == std::numeric_limits<int>::min()) return result;
  result.exponent = 1 - E;  // the longest side times 2^exponent is in [1, 2)
  // Far from the origin (the centre beyond 4 * 2^E on an axis): translate that axis by the
  // centre rounded to a multiple of 2^E. Then |x| >= 2^(E+1), so x's unit in the last place is
  // at least 2^(E-51), and |x - offset| <= 2^E: the difference has at most 52 significant bits
  // and is computed exactly.
  for (int k = 0; k < D; ++k) {
    const double centre = 0.5 * lo[k] + 0.5 * hi[k];
    if (std::abs(centre) >= std::ldexp(4.0, E)) {
      result.offset[k] = std::ldexp(std::nearbyint(std::ldexp(centre, -E)), E);
      if (!std::isfinite(result.offset[k])) result.offset[k] = 0;
    }
  }
  return result;
}

// The point with the largest coordinate (in size), named with it: what a set too widely spread
// is measured against, often one stray point (it may be the point refused itself).
template <int D>
std::string point_of_largest_coordinate(const std::vector<Point<D>>& samples) {
  std::size_t farthest = 0;
  double largest = -1;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (double x : samples[i]) {
      if (std::abs(x) > largest) largest = std::abs(x), farthest = i;
    }
  }
  return ordinal_point(farthest) + " " + describe_point<D>(samples[farthest]);
}

// The normalised samples; throws Input_error where the spread of the coordinates cannot be
// represented (a coordinate lost in the normalisation, or too small against the extent).
template <int D>
std::vector<Point<D>> normalised(const std::vector<Point<D>>& samples, const Normalisation<D>& n) {
  std::vector<Point<D>> result;
  result.reserve(samples.size());
  const double smallest = std::ldexp(1.0, smallest_normalised_exponent);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Point<D> p = n.apply(samples[i]);
    for (int k = 0; k < D; ++k) {
      if (p[k] != 0 && std::abs(p[k]) < smallest) {
        throw Input_error(ordinal_point(i) + " has a coordinate too small against " +
                          point_of_largest_coordinate<D>(samples) +
                          " (more than 120 orders of magnitude apart) to be represented with it");
      }
    }
    if (n.undo(p) != samples[i]) {
      throw Input_error(ordinal_point(i) +
                        " cannot be represented exactly together with the others: the "
                        "coordinates span too many orders of magnitude (" +
                        point_of_largest_coordinate<D>(samples) + ")");
    }
    result.push_back(p);
  }
  return result;
}

// Brings a reconstruction made from normalised samples back to the input's coordinates: the
// samples exactly as given, the box corners, inserted poles and poles mapped back.
template <int D>
void undo_normalisation(Reconstruction<D>& result, const Normalisation<D>& n,
                        const std::vector<Point<D>>& samples) {
  if (n.identity()) return;
  for (std::size_t i = 0; i < result.sites.size(); ++i) {
    result.sites[i] = i < samples.size() ? samples[i] : n.undo(result.sites[i]);
  }
  for (auto& pole : result.poles.poles) {
    pole.center = n.undo(pole.center);
    pole.radius = std::ldexp(pole.radius, -n.exponent);
  }
  for (auto& vertex : result.crust.voronoi_vertices) vertex = n.undo(vertex);
  for (auto& vertex : result.surface_vertices) vertex = n.undo(vertex);
}

}  // namespace sculpt
