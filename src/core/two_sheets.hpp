// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a sample's neighbours lie on two sheets, not one: both sides of a wall thinner than
// the neighbourhood (a plate, a fin, a flange).
//
// A quadric fitted to one noisy sheet leaves residuals in one bump, the noise; fitted across a
// wall it runs down the middle and leaves two, the wall's thickness apart, however clean the
// samples are. Read as noise, a clean plate 0.02 thick (about its spacing) measured 0.54 of its
// spacing, was smoothed, and came back torn. So the neighbours are fitted as two parallel
// sheets, a quadric q and each point on its side s = ±1 of it, h = q(u, v) + s t:
//
//   s <- the sign of each point's residual over the quadric through all
//   a few times: q <- the quadric through h - s t; t <- the mean of s (h - q); s <- sign(h - q)
//   two sheets when each side holds at least sheet_at_least points and the sheets lie at least
//   sheets_apart standard deviations of what is left (h - q - s t) apart: 2 t >= 4 sd (and
//   apart at all: points exactly on one plane are one sheet)
//
// One sheet of Gaussian noise splits at its middle, the halves ±0.80 σ, 0.60 σ about them: 2.65
// deviations apart; 4 leaves room for the spread of 15 points (the noise measure's neighbourhood;
// fewer than 2 sheet_at_least + 7 points, the unknowns q and t, are never two sheets).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "quadric_fit.hpp"

namespace sculpt {

inline constexpr double sheets_apart = 4.0;
inline constexpr int sheet_at_least = 4;

// `points`: (u, v, h) in a frame over the neighbours' best plane.
inline bool lie_on_two_sheets(const std::vector<std::array<double, 3>>& points) {
  const std::size_t count = points.size();
  const std::size_t at_least = sheet_at_least;
  if (count < 2 * at_least + 7) return false;  // 7 unknowns: q and t
  std::vector<double> heights(count), side(count);
  for (std::size_t j = 0; j < count; ++j) heights[j] = points[j][2];
  double q[6];
  if (!fit_quadric(points, heights, q)) return false;
  for (std::size_t j = 0; j < count; ++j) {
    side[j] = points[j][2] >= quadric_at(q, points[j][0], points[j][1]) ? 1 : -1;
  }
  double t = 0;
  for (int round = 0; round < 4; ++round) {
    for (std::size_t j = 0; j < count; ++j) heights[j] = points[j][2] - side[j] * t;
    if (!fit_quadric(points, heights, q)) return false;
    t = 0;
    for (std::size_t j = 0; j < count; ++j) {
      t += side[j] * (points[j][2] - quadric_at(q, points[j][0], points[j][1])) / double(count);
    }
    for (std::size_t j = 0; j < count; ++j) {
      side[j] = points[j][2] >= quadric_at(q, points[j][0], points[j][1]) ? 1 : -1;
    }
  }
  std::size_t above = 0;
  double squares = 0;
  for (std::size_t j = 0; j < count; ++j) {
    above += side[j] > 0;
    const double left = points[j][2] - quadric_at(q, points[j][0], points[j][1]) - side[j] * t;
    squares += left * left;
  }
  if (above < at_least || count - above < at_least) return false;
  const double deviation = std::sqrt(squares / double(count - 7));
  return t > 0 && 2 * t >= sheets_apart * deviation;
}

}  // namespace sculpt
