// SPDX-License-Identifier: GPL-3.0-or-later
// The 3D shapes: closed and bordered surfaces, sampled regularly or at random.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

#include "shapes.hpp"

namespace sculpt::shapes {
namespace {

constexpr double pi = 3.14159265358979323846;

}  // namespace

std::vector<Point<3>> sphere(int samples) {
  // Fibonacci lattice: nearly uniform, no four points cospherical by construction.
  std::vector<Point<3>> points;
  const double golden = pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < samples; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / samples;
    const double r = std::sqrt(1.0 - z * z);
    points.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
  }
  return points;
}

std::vector<Point<3>> torus(int samples, double major, double minor, unsigned seed) {
  // Uniform by area: accept an angle v with probability (R + r cos v) / (R + r).
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point<3>> points;
  points.reserve(samples);
  while (static_cast<int>(points.size()) < samples) {
    const double u = 2 * pi * unit(random), v = 2 * pi * unit(random);
    if (unit(random) * (major + minor) > major + minor * std::cos(v)) continue;
    const double ring = major + minor * std::cos(v);
    points.push_back({ring * std::cos(u), ring * std::sin(u), minor * std::sin(v)});
  }
  return points;
}

std::vector<Point<3>> noisy_sphere(int samples, double noise, unsigned seed) {
  // Directions uniform on the sphere (normalised Gaussians), radii 1 + N(0, noise * spacing),
  // where the spacing is that of `samples` points spread evenly over the area 4 pi.
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double spacing = std::sqrt(4 * pi / samples);
  std::vector<Point<3>> points;
  points.reserve(samples);
  while (static_cast<int>(points.size()) < samples) {
    Point<3> p{normal(random), normal(random), normal(random)};
    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (length < 1e-9) continue;
    const double radius = 1.0 + noise * spacing * normal(random);
    for (double& x : p) x *= radius / length;
    points.push_back(p);
  }
  return points;
}

std::vector<Point<3>> bumpy_sphere(int samples) {
  std::vector<Point<3>> points = sphere(samples);
  for (auto& p : points) {
    // Radius modulated by a cubic harmonic: dents and bumps along the axes' diagonals.
    const double bump = p[0] * p[0] * p[0] * p[0] + p[1] * p[1] * p[1] * p[1] +
                        p[2] * p[2] * p[2] * p[2];  // 1 on the axes, 1/3 on the diagonals
    const double r = 0.75 + 0.45 * (bump - 0.6);
    for (double& x : p) x *= r;
  }
  return points;
}

std::vector<Point<3>> saddle(int samples_per_side) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Point<3>> points;
  const double step = 2.0 / (samples_per_side - 1);
  for (int i = 0; i < samples_per_side; ++i) {
    for (int j = 0; j < samples_per_side; ++j) {
      const bool border_x = i == 0 || i == samples_per_side - 1;
      const bool border_y = j == 0 || j == samples_per_side - 1;
      const double x = -1.0 + step * (i + (border_x ? 0.0 : jitter(random)));
      const double y = -1.0 + step * (j + (border_y ? 0.0 : jitter(random)));
      points.push_back({x, y, x * x - y * y});
    }
  }
  return points;
}

std::vector<Point<3>> monkey_saddle(int samples_per_side) {
  auto points = saddle(samples_per_side);
  for (auto& p : points) p[2] = 0.35 * (p[0] * p[0] * p[0] - 3 * p[0] * p[1] * p[1]);
  return points;
}

std::vector<Point<3>> hemisphere(int samples) {
  std::vector<Point<3>> points;
  for (const auto& p : sphere(2 * samples)) {
    if (p[2] >= 0) points.push_back(p);
  }
  return points;
}

std::vector<Point<3>> open_cylinder(int samples) {
  // Rows of samples around the axis, each row offset by half a step from the last so the
  // samples form near-equilateral triangles; the inner rows are jittered, the two end rows are
  // exact circles: the borders.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const double height = 3.0;
  const int rows = static_cast<int>(std::sqrt(samples * height / (2 * pi)));
  const int columns = samples / rows;
  std::vector<Point<3>> points;
  for (int row = 0; row < rows; ++row) {
    const bool end_row = row == 0 || row == rows - 1;
    for (int column = 0; column < columns; ++column) {
      const double angle =
          2 * pi * (column + 0.5 * (row % 2) + (end_row ? 0.0 : jitter(random))) / columns;
      const double z = -height / 2 + height * (row + (end_row ? 0.0 : jitter(random))) / (rows - 1);
      points.push_back({std::cos(angle), std::sin(angle), z});
    }
  }
  return points;
}

std::vector<Point<3>> wavy_annulus(int samples) {
  // A sunflower spiral restricted to radii 0.5 to 1 (uniform by area), lifted by a wave of
  // three periods around the axis.
  const double golden = pi * (3.0 - std::sqrt(5.0));
  std::vector<Point<3>> points;
  for (int i = 0; i < samples; ++i) {
    const double r = std::sqrt(0.25 + 0.75 * (i + 0.5) / samples);
    const double angle = golden * i;
    points.push_back({r * std::cos(angle), r * std::sin(angle), 0.12 * r * std::sin(3 * angle)});
  }
  return points;
}

std::vector<Point<3>> sphere_with_holes(int samples) {
  // Three round holes, of angular radius 0.35, 0.5 and 0.7, around the three axes. The
  // smallest is about 4.6 spacings (sixth-neighbour distances, 0.075) wide in radius: an opening
  // both the bordered rule and the kind choice tell from a gap in the sampling
  // (core/spanning_openings.hpp).
  const std::array<std::pair<int, double>, 3> holes = {{{0, 0.35}, {1, 0.5}, {2, 0.7}}};
  std::vector<Point<3>> points;
  for (const auto& p : sphere(samples)) {
    bool in_hole = false;
    for (const auto& [axis, radius] : holes) in_hole = in_hole || p[axis] >= std::cos(radius);
    if (!in_hole) points.push_back(p);
  }
  return points;
}

std::vector<Point<3>> torus_knot_tube(int samples, unsigned seed) {
  // The (2,3) torus knot c(t) on a torus of radii 1 and 0.45, with a tube of radius 0.16 around
  // it; points are spread evenly in t and in the angle around the tube.
  const auto knot = [](double t) {
    const double r = 1.0 + 0.45 * std::cos(3 * t);
    return std::array<double, 3>{r * std::cos(2 * t), r * std::sin(2 * t), 0.45 * std::sin(3 * t)};
  };
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point<3>> points;
  const double tube = 0.16, h = 1e-4;
  for (int i = 0; i < samples; ++i) {
    const double t = 2 * pi * (i + 0.5 * unit(random)) / samples;
    const double angle = 2 * pi * unit(random);
    const auto c = knot(t), ahead = knot(t + h);
    std::array<double, 3> tangent{ahead[0] - c[0], ahead[1] - c[1], ahead[2] - c[2]};
    const double tl =
        std::sqrt(tangent[0] * tangent[0] + tangent[1] * tangent[1] + tangent[2] * tangent[2]);
    for (double& x : tangent) x /= tl;
    // A frame around the tangent: one normal from the z axis, the other by the cross product.
    std::array<double, 3> n1{-tangent[1], tangent[0], 0.0};
    const double nl = std::sqrt(n1[0] * n1[0] + n1[1] * n1[1]);
    for (double& x : n1) x /= nl;
    const std::array<double, 3> n2{tangent[1] * n1[2] - tangent[2] * n1[1],
                                   tangent[2] * n1[0] - tangent[0] * n1[2],
                                   tangent[0] * n1[1] - tangent[1] * n1[0]};
    Point<3> p;
    for (int k = 0; k < 3; ++k)
      p[k] = c[k] + tube * (std::cos(angle) * n1[k] + std::sin(angle) * n2[k]);
    points.push_back(p);
  }
  return points;
}

std::vector<Point<3>> three_holes(int samples, unsigned seed) {
  // Three tori side by side, blended into one smooth solid with three holes: the smooth
  // minimum of their distance functions. Samples of each torus that lie outside the others are
  // projected onto the blended surface by a few Newton steps.
  const double major = 1.0, minor = 0.35, spacing = 1.8, blend = 0.12;
  const auto torus_distance = [&](const Point<3>& p, int which) {
    const double x = p[0] - spacing * (which - 1);
    return std::hypot(std::hypot(x, p[1]) - major, p[2]) - minor;
  };
  const auto distance = [&](const Point<3>& p) {
    double sum = 0;
    for (int which = 0; which < 3; ++which) sum += std::exp(-torus_distance(p, which) / blend);
    return -blend * std::log(sum);
  };
  std::vector<Point<3>> points;
  for (int which = 0; which < 3; ++which) {
    for (auto p : torus(samples / 3 + samples / 10, major, minor, seed + which)) {
      p[0] += spacing * (which - 1);
      bool covered = false;
      for (int other = 0; other < 3; ++other) {
        covered = covered || (other != which && torus_distance(p, other) < 0.02);
      }
      if (covered) continue;
      for (int step = 0; step < 6; ++step) {
        const double d = distance(p), h = 1e-6;
        Point<3> gradient;
        for (int k = 0; k < 3; ++k) {
          Point<3> q = p;
          q[k] += h;
          gradient[k] = (distance(q) - d) / h;
        }
        const double g2 =
            gradient[0] * gradient[0] + gradient[1] * gradient[1] + gradient[2] * gradient[2];
        for (int k = 0; k < 3; ++k) p[k] -= d * gradient[k] / g2;
      }
      points.push_back(p);
    }
  }
  return points;
}

std::vector<Point<3>> torso(int samples) {
  std::vector<Point<3>> points = sphere(samples);
  for (auto& p : points) {
    const double height = p[2];  // up the body, which stands along y
    const double waist = 1.0 - 0.18 * std::exp(-std::pow((height + 0.1) / 0.35, 2));
    const double shoulders =
        1.0 + 0.35 * std::exp(-std::pow((height - 0.55) / 0.25, 2)) * p[0] * p[0];
    const double depth = p[1];
    p = {p[0] * 0.75 * waist * shoulders, height * 1.3, depth * 0.42 * waist};
  }
  return points;
}

std::vector<Point<3>> thinned_on_one_side(const std::vector<Point<3>>& points, int ratio) {
  std::vector<Point<3>> kept;
  int count = 0;
  for (const auto& p : points) {
    if (p[0] < 0 || count++ % ratio == 0) kept.push_back(p);
  }
  return kept;
}

}  // namespace sculpt::shapes
