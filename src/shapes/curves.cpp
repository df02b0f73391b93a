// SPDX-License-Identifier: GPL-3.0-or-later
// The 2D shapes: closed and open curves sampled by arc length, with their true edges, and
// polylines resampled as strokes.
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "shapes.hpp"

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

}  // namespace sculpt::shapes
