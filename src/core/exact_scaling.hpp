// Extreme but finite scales (a sphere of radius 1e80 or 1e-105, denormal coordinates) overflow
// or underflow the squared distances and circumradii every stage computes in floating point.
// The samples are scaled by a power of two so that the longest side of their bounding box lies
// in [1, 2). Multiplying by a power of two is exact and commutes with rounding, so every
// predicate and construction gives the same answer as on the input as given (which it would,
// had it not overflowed); every stored stage is scaled back at the end.
#pragma once

#include <algorithm>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

// The exponent k such that the samples times 2^k have a bounding box whose longest side is in
// [1, 2); 0 for a single point.
template <int D>
int normalising_exponent(const std::vector<Point<D>>& samples) {
  double longest = 0;
  for (int k = 0; k < D; ++k) {
    const auto [lo, hi] =
        std::minmax_element(samples.begin(), samples.end(),
                            [k](const Point<D>& a, const Point<D>& b) { return a[k] < b[k]; });
    // hi - lo can overflow for huge coordinates of both signs: compare halves.
    longest = std::max(longest, 0.5 * (*hi)[k] - 0.5 * (*lo)[k]);
  }
  if (!(longest > 0) || !std::isfinite(longest)) return 0;
  int exponent = 0;
  std::frexp(longest, &exponent);  // longest = m 2^exponent, m in [0.5, 1): the side is m 2^(e+1)
  return -exponent;
}

template <int D>
Point<D> scaled(Point<D> p, int exponent) {
  for (double& x : p) x = std::ldexp(x, exponent);
  return p;
}

template <int D>
std::vector<Point<D>> scaled(const std::vector<Point<D>>& points, int exponent) {
  std::vector<Point<D>> result;
  result.reserve(points.size());
  for (const auto& p : points) result.push_back(scaled<D>(p, exponent));
  return result;
}

// Brings a reconstruction made from scaled samples back to the scale of the input.
template <int D>
void scale_back(Reconstruction<D>& result, int exponent) {
  if (exponent == 0) return;
  for (auto& site : result.sites) site = scaled<D>(site, -exponent);
  for (auto& pole : result.poles.poles) {
    pole.center = scaled<D>(pole.center, -exponent);
    pole.radius = std::ldexp(pole.radius, -exponent);
  }
}

}  // namespace sculpt
