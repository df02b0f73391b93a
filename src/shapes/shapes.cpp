// SPDX-License-Identifier: GPL-3.0-or-later
#include "shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

namespace sculpt::shapes {
namespace {

constexpr double pi = 3.14159265358979323846;

Point<2> on_circle(double radius, double angle) {
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

void close_polygon(Sampled_curve& curve, int first, int count) {
  for (int i = 0; i < count; ++i) curve.edges.push_back({first + i, first + (i + 1) % count});
}

// Samples at equal shares of the density integrated along arc length: `samples` of them over
// [0, 1), or over [0, 1] with both ends when `include_end`.
std::vector<Point<2>> sample_by_arc_length(const std::function<Point<2>(double)>& curve,
                                           int samples,
                                           const std::function<double(double)>& density,
                                           bool include_end) {
  // Integrate density along arc length on a fine polyline, then cut it into equal shares.
  const int steps = std::max(20000, samples * 50);
  std::vector<double> t(steps + 1), weight(steps + 1, 0.0);
  Point<2> previous = curve(0.0);
  for (int i = 1; i <= steps; ++i) {
    t[i] = double(i) / steps;
    const Point<2> p = curve(t[i]);
    const double length = std::hypot(p[0] - previous[0], p[1] - previous[1]);
    const double w = density ? density(0.5 * (t[i] + t[i - 1])) : 1.0;
    weight[i] = weight[i - 1] + length * w;
    previous = p;
  }
  std::vector<Point<2>> points;
  const int shares = include_end ? samples - 1 : samples;
  for (int k = 0; k < samples; ++k) {
    const double target = weight.back() * k / shares;
    // Rounding can put the last target a hair beyond the total: it is the curve's end.
    const auto i = std::min<std::ptrdiff_t>(
        std::lower_bound(weight.begin(), weight.end(), target) - weight.begin(), steps);
    const double a = i == 0 ? 0 : (target - weight[i - 1]) / (weight[i] - weight[i - 1]);
    points.push_back(curve(i == 0 ? 0.0 : t[i - 1] + a * (t[i] - t[i - 1])));
  }
  return points;
}

Point<2> on_blob(double angle) {
  const double r = 1.0 + 0.25 * std::sin(2 * angle + 0.4) + 0.15 * std::cos(3 * angle) +
                   0.08 * std::sin(5 * angle + 1.0);
  return {1.3 * r * std::cos(angle), r * std::sin(angle)};
}

void join_in_order(Sampled_curve& curve, int first, int count) {
  for (int i = 0; i + 1 < count; ++i) curve.edges.push_back({first + i, first + i + 1});
}

}  // namespace

Sampled_curve sample_closed_curve(const std::function<Point<2>(double)>& curve, int samples,
                                  const std::function<double(double)>& density) {
  Sampled_curve result;
  result.samples = sample_by_arc_length(curve, samples, density, /*include_end=*/false);
  close_polygon(result, 0, samples);
  return result;
}

Sampled_curve sample_open_curve(const std::function<Point<2>(double)>& curve, int samples) {
  Sampled_curve result;
  result.samples = sample_by_arc_length(curve, samples, {}, /*include_end=*/true);
  join_in_order(result, 0, samples);
  return result;
}

Sampled_curve wavy_arc(double degrees, int samples_per_turn) {
  const double span = degrees * pi / 180;
  // The blob's samples are equally spaced by arc length; so are these, at the same spacing.
  double length = 0, turn = 0;
  Point<2> previous = on_blob(0);
  for (int i = 1; i <= 20000; ++i) {
    const double angle = 2 * pi * i / 20000;
    const Point<2> p = on_blob(angle);
    const double step = std::hypot(p[0] - previous[0], p[1] - previous[1]);
    turn += step;
    if (angle <= span) length += step;
    previous = p;
  }
  const int samples = std::max(2, int(std::lround(samples_per_turn * length / turn)) + 1);
  return sample_open_curve([=](double t) { return on_blob(span * t); }, samples);
}

Sampled_curve spiral(double turns, double spacing) {
  // r = 1 + θ / 2π: arms one unit apart, the innermost turn of radius 1.
  const auto at = [=](double t) {
    const double angle = 2 * pi * turns * t;
    return on_circle(1.0 + angle / (2 * pi), angle);
  };
  double length = 0;
  for (int i = 1; i <= 20000; ++i) {
    const Point<2> a = at((i - 1) / 20000.0), b = at(i / 20000.0);
    length += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  return sample_open_curve(at, int(std::ceil(length / spacing)) + 1);
}

Sampled_curve two_strokes(double gap, int samples_per_stroke) {
  Sampled_curve result;
  for (int stroke = 0; stroke < 2; ++stroke) {
    const double phase = stroke, y = stroke * gap;
    const int first = int(result.samples.size());
    Sampled_curve one = sample_open_curve(
        [=](double t) {
          const double x = 2.0 * t;
          return Point<2>{x, y + 0.1 * std::sin(3 * x + phase)};
        },
        samples_per_stroke);
    result.samples.insert(result.samples.end(), one.samples.begin(), one.samples.end());
    join_in_order(result, first, samples_per_stroke);
  }
  return result;
}

Sampled_curve circle(int samples) {
  Sampled_curve result;
  for (int i = 0; i < samples; ++i) result.samples.push_back(on_circle(1.0, 2 * pi * i / samples));
  close_polygon(result, 0, samples);
  return result;
}

Sampled_curve star(int samples, int arms, double depth) {
  return sample_closed_curve(
      [=](double t) { return on_circle(1.0 + depth * std::cos(arms * 2 * pi * t), 2 * pi * t); },
      samples);
}

Sampled_curve blob(int samples) {
  return sample_closed_curve([](double t) { return on_blob(2 * pi * t); }, samples);
}

Sampled_curve nested_circles(int outer_samples, int inner_samples) {
  Sampled_curve result;
  for (int i = 0; i < outer_samples; ++i) {
    result.samples.push_back(on_circle(1.0, 2 * pi * (i + 0.5) / outer_samples));
  }
  close_polygon(result, 0, outer_samples);
  // The hole's border runs clockwise, so the annulus lies on the left of every edge.
  for (int i = 0; i < inner_samples; ++i) {
    result.samples.push_back(on_circle(0.5, -2 * pi * (i + 0.25) / inner_samples));
  }
  close_polygon(result, outer_samples, inner_samples);
  return result;
}

Sampled_curve nonuniform_ellipse(int samples, double ratio) {
  // Density runs smoothly from 1 to `ratio` and back along the curve.
  return sample_closed_curve(
      [](double t) {
        return Point<2>{1.5 * std::cos(2 * pi * t), std::sin(2 * pi * t)};
      },
      samples, [=](double t) { return 1.0 + (ratio - 1.0) * 0.5 * (1 - std::cos(2 * pi * t)); });
}

Sampled_curve open_arc(int samples) {
  Sampled_curve result;
  for (int i = 0; i < samples; ++i) {
    result.samples.push_back(on_circle(1.0, 1.5 * pi * i / (samples - 1)));
  }
  for (int i = 0; i + 1 < samples; ++i) result.edges.push_back({i, i + 1});
  return result;
}

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

const std::vector<Example>& examples() {
  static const std::vector<Example> list = {
      {"circle", 2, "64 samples on a circle", false},
      {"star", 2, "a five-armed star, 200 samples", false},
      {"blob", 2, "a smooth blob, 150 samples", false},
      {"blob-dense", 2, "the same blob, 600 samples", false},
      {"nested", 2, "two nested circles (an annulus), 120 + 60 samples", false},
      {"nonuniform", 2, "an ellipse sampled 9:1 non-uniformly, 200 samples", false},
      {"arc", 2, "an open three-quarter circle, 60 samples (bordered)", true},
      {"wavy-arc", 2, "340 degrees of the blob's outline: an open curve nearly closed (bordered)",
       true},
      {"spiral", 2, "an open spiral of 2.5 turns, 179 samples (bordered)", true},
      {"strokes", 2, "two wavy open strokes side by side, 41 samples each (bordered)", true},
      {"bracket", 2,
       "a bracket with sharp corners, a slot narrower than the spacing and a noisy end, 160 "
       "samples: the methods differ",
       false},
      {"sphere", 3, "2000 samples on a sphere", false},
      {"torus", 3, "4000 random samples on a torus (genus 1)", false},
      {"bumpy", 3, "a sphere with dents and bumps, 6000 samples", false},
      {"saddle", 3, "the saddle z = x^2 - y^2, 40 x 40 jittered samples (bordered)", true},
      {"monkey-saddle", 3, "the monkey saddle z = x^3 - 3xy^2, 40 x 40 samples (bordered)", true},
      {"hemisphere", 3, "half a sphere, 3000 samples (bordered)", true},
      {"open-cylinder", 3, "a tube open at both ends, about 3000 jittered samples (bordered)",
       true},
      {"wavy-annulus", 3, "a wavy ring: a sheet with an outer and an inner border (bordered)",
       true},
      {"holey-sphere", 3, "a sphere with three round holes of different sizes (bordered)", true},
      {"torso", 3, "a smooth torso-like blob, 8000 samples", false},
      {"torus-knot", 3, "a tube around a (2,3) torus knot, 12000 samples", false},
      {"three-holes", 3, "three overlapping tori: a solid with three holes, ~10000 samples", false},
      {"bumpy-nonuniform", 3, "the bumpy sphere thinned 3:1 on its +x side", false},
      {"drilled-block", 3,
       "a block with a hole: sharp edges, a sparse back and a noisy end, 4000 samples: the "
       "methods differ",
       false},
  };
  return list;
}

const Example* find_example(const std::string& name) {
  for (const auto& example : examples()) {
    if (example.name == name) return &example;
  }
  return nullptr;
}

std::vector<Point<2>> example_points_2(const std::string& name) {
  if (name == "circle") return circle(64).samples;
  if (name == "star") return star(200).samples;
  if (name == "blob") return blob(150).samples;
  if (name == "blob-dense") return blob(600).samples;
  if (name == "nested") return nested_circles(120, 60).samples;
  if (name == "nonuniform") return nonuniform_ellipse(200).samples;
  if (name == "arc") return open_arc(60).samples;
  if (name == "wavy-arc") return wavy_arc(340).samples;
  if (name == "spiral") return spiral().samples;
  if (name == "strokes") return two_strokes().samples;
  if (name == "bracket") return bracket(160).samples;
  throw std::invalid_argument("no 2D example named '" + name + "'");
}

Sampled_curve example_curve_2(const std::string& name) {
  constexpr int dense = 10;
  if (name == "circle") return circle(64 * dense);
  if (name == "star") return star(200 * dense);
  if (name == "blob" || name == "blob-dense") return blob(600 * dense);
  if (name == "nested") return nested_circles(120 * dense, 60 * dense);
  if (name == "nonuniform") return nonuniform_ellipse(200 * dense);
  if (name == "arc") return open_arc(60 * dense);
  if (name == "wavy-arc") return wavy_arc(340, 150 * dense);
  if (name == "spiral") return spiral(2.5, 0.2 / dense);
  if (name == "strokes") return two_strokes(0.5, 40 * dense + 1);
  if (name == "bracket") return bracket(160 * dense, /*noisy=*/false);
  throw std::invalid_argument("no 2D example named '" + name + "'");
}

std::vector<Point<2>> resample_polyline(const std::vector<Point<2>>& polyline, double spacing,
                                        std::size_t most) {
  std::vector<Point<2>> samples;
  if (polyline.empty() || !(spacing > 0) || most < 2) return samples;
  double total = 0;
  for (std::size_t i = 1; i < polyline.size(); ++i)
    total += std::hypot(polyline[i][0] - polyline[i - 1][0], polyline[i][1] - polyline[i - 1][1]);
  if (!std::isfinite(total)) return samples;
  // No more than `most` samples: a spacing too fine for the stroke's length is widened (and
  // stays large enough for the walk along it to move on).
  spacing = std::max(spacing, total / double(most - 1));
  samples.push_back(polyline.front());
  double since_last = 0;  // arc length walked since the last sample
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const Point<2>& a = polyline[i - 1];
    const Point<2>& b = polyline[i];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    double at = spacing - since_last;  // where on this segment the next sample falls
    for (; at <= length; at += spacing) {
      const double t = at / length;
      samples.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
    since_last = length - (at - spacing);
  }
  // The stroke's end is a sample too, unless the last one nearly is it already.
  const Point<2>& end = polyline.back();
  const Point<2>& last = samples.back();
  if (std::hypot(end[0] - last[0], end[1] - last[1]) > spacing / 2) {
    samples.push_back(end);
  } else if (samples.size() > 1) {
    samples.back() = end;
  }
  return samples;
}

std::vector<Point<3>> example_points_3(const std::string& name) {
  if (name == "sphere") return sphere(2000);
  if (name == "torus") return torus(4000);
  if (name == "bumpy") return bumpy_sphere(6000);
  if (name == "saddle") return saddle(40);
  if (name == "monkey-saddle") return monkey_saddle(40);
  if (name == "hemisphere") return hemisphere(3000);
  if (name == "open-cylinder") return open_cylinder(3000);
  if (name == "wavy-annulus") return wavy_annulus(3000);
  if (name == "holey-sphere") return sphere_with_holes(4000);
  if (name == "torso") return torso(8000);
  if (name == "torus-knot") return torus_knot_tube(12000);
  if (name == "three-holes") return three_holes(10000);
  if (name == "bumpy-nonuniform") return thinned_on_one_side(bumpy_sphere(6000), 3);
  if (name == "drilled-block") return drilled_block(4000);
  throw std::invalid_argument("no 3D example named '" + name + "'");
}

}  // namespace sculpt::shapes
