// SPDX-License-Identifier: GPL-3.0-or-later
// Two examples made for comparing methods: each has, in one part, what sets the methods apart
// (sharp corners, a feature narrower than the sampling, a noisy side, a sparse side), so that
// side by side they visibly differ, and each part shows a different one failing.
#include <array>
#include <cmath>
#include <vector>

#include "portable_random.hpp"
#include "shapes.hpp"

namespace sculpt::shapes {
namespace {

constexpr double pi = 3.14159265358979323846;

// A closed polygon walked at constant speed: t in [0, 1) to a point of its outline.
Point<2> along_polygon(const std::vector<Point<2>>& corners, double t) {
  std::vector<double> lengths;
  double total = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    lengths.push_back(std::hypot(b[0] - a[0], b[1] - a[1]));
    total += lengths.back();
  }
  double at = (t - std::floor(t)) * total;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (at <= lengths[i] || i + 1 == corners.size()) {
      const auto& a = corners[i];
      const auto& b = corners[(i + 1) % corners.size()];
      const double s = lengths[i] > 0 ? std::min(1.0, at / lengths[i]) : 0.0;
      return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
    }
    at -= lengths[i];
  }
  return corners.front();
}

// A bracket 2 by 1.2, counterclockwise: a tooth of 53 degrees at its foot, and a slot 0.06 wide
// and 0.6 deep cut into its top, narrower than the samples' spacing.
const std::vector<Point<2>>& bracket_corners() {
  static const std::vector<Point<2>> corners = {
      {-1.0, -0.6}, {-0.55, -0.6}, {-0.45, -0.95}, {-0.35, -0.6}, {1.0, -0.6}, {1.0, 0.6},
      {0.1, 0.6},   {0.1, 0.0},    {0.04, 0.0},    {0.04, 0.6},   {-1.0, 0.6}};
  return corners;
}

}  // namespace

Sampled_curve bracket(int samples, bool noisy) {
  Sampled_curve curve =
      sample_closed_curve([](double t) { return along_polygon(bracket_corners(), t); }, samples);
  if (!noisy) return curve;
  // Noise of 0.4% of the width on the right end: a curve through every sample zigzags there.
  Portable_random random(7);
  for (auto& p : curve.samples) {
    if (p[0] > 0.5) {
      p[0] += 0.008 * random.normal();
      p[1] += 0.008 * random.normal();
    }
  }
  return curve;
}

std::vector<Point<3>> drilled_block(int samples, unsigned seed) {
  // A block [-1, 1] x [-0.7, 0.7] x [-0.4, 0.4] drilled through along z by a hole of radius
  // 0.3 at x = -0.3: sharp edges all round, genus 1. Sampled uniformly by area.
  constexpr double a = 1.0, b = 0.7, c = 0.4, hole = 0.3, hole_x = -0.3;
  const std::array<double, 4> areas = {
      2 * (4 * a * b),         // top and bottom (a pick in the hole is drawn again)
      2 * (2 * a * 2 * c),     // the faces across y
      2 * (2 * b * 2 * c),     // the faces across x
      2 * pi * hole * 2 * c};  // the hole's wall
  const double total = areas[0] + areas[1] + areas[2] + areas[3];
  Portable_random random(seed);
  std::vector<Point<3>> points;
  int count = 0;
  while (int(points.size()) < samples) {
    double pick = random.unit() * total;
    int face = 0;
    while (face < 3 && pick >= areas[face]) pick -= areas[face++];
    const double u = 2 * random.unit() - 1, v = 2 * random.unit() - 1;
    const double side = random.unit() < 0.5 ? -1.0 : 1.0;
    Point<3> p{};
    switch (face) {
      case 0:
        p = {a * u, b * v, c * side};
        if (std::hypot(p[0] - hole_x, p[1]) < hole) continue;
        break;
      case 1:
        p = {a * u, b * side, c * v};
        break;
      case 2:
        p = {a * side, b * u, c * v};
        break;
      default: {
        const double angle = pi * u;
        p = {hole_x + hole * std::cos(angle), hole * std::sin(angle), c * v};
      }
    }
    // Sparse at the back (one sample in three), noisy at the right end (0.3% of the diagonal).
    if (p[1] < -0.35 && count++ % 3 != 0) continue;
    if (p[0] > 0.45) {
      for (auto& x : p) x += 0.01 * random.normal();
    }
    points.push_back(p);
  }
  return points;
}

}  // namespace sculpt::shapes
