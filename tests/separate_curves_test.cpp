// SPDX-License-Identifier: GPL-3.0-or-later
// 2D: closed curves that are apart stay apart. Two, three and nested circles at every spacing,
// each sampled as densely as epsilon = 0.5 asks (every point of a curve within half its local
// feature size of a sample: the distance to the nearest other curve counts), come back as
// exactly their polygons, one component each, by the robust method. The paper's method keeps two
// curves apart too, but joins the middle one of three in a row to a neighbour (a branching
// sample): it is kept as published.
#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "test_support.hpp"

namespace sculpt {
namespace {

struct Circle {
  Point<2> center;
  double radius;
};

struct Drawing {
  std::vector<Point<2>> samples;
  std::vector<Facet<2>> edges;
};

// The local feature size along a circle, bounded by its radius (its medial axis is its centre)
// and by half the distance to each other circle (their medial axis runs between them).
double feature_size(const Circle& c, const std::vector<Circle>& all) {
  double size = c.radius;
  for (const Circle& other : all) {
    if (&other == &c) continue;
    const double d = std::hypot(other.center[0] - c.center[0], other.center[1] - c.center[1]);
    const double gap = d >= c.radius + other.radius
                           ? d - c.radius - other.radius             // apart
                           : std::abs(c.radius - other.radius) - d;  // nested
    size = std::min(size, gap / 2);
  }
  return size;
}

// Each circle with as few samples as epsilon allows: a point between two samples is at most
// half a chord from one, pi r / n <= epsilon * lfs. A phase per circle keeps samples of
// different circles off common lines.
Drawing sampled(const std::vector<Circle>& circles, double epsilon) {
  Drawing drawing;
  double phase = 0.1;
  for (const Circle& c : circles) {
    const int n =
        static_cast<int>(std::ceil(M_PI * c.radius / (epsilon * feature_size(c, circles))));
    const int first = static_cast<int>(drawing.samples.size());
    for (int i = 0; i < n; ++i) {
      const double a = phase + 2 * M_PI * i / n;
      drawing.samples.push_back(
          {c.center[0] + c.radius * std::cos(a), c.center[1] + c.radius * std::sin(a)});
      drawing.edges.push_back({first + i, first + (i + 1) % n});
    }
    phase += 0.37;
  }
  return drawing;
}

void expect_each_curve_alone(const std::vector<Circle>& circles, const std::string& name,
                             std::vector<Method> methods = {Method::robust}) {
  const Drawing drawing = sampled(circles, 0.5);
  for (Method method : methods) {
    SCOPED_TRACE(name + ", " + to_string(method) + ", " + std::to_string(drawing.samples.size()) +
                 " samples");
    Options options;
    options.method = method;
    const auto result = reconstruct(drawing.samples, options);
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(drawing.edges));
    EXPECT_EQ(result.stats.components, circles.size());
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
  }
}

TEST(Separate_curves, TwoCirclesStayApartAtEverySpacing) {
  for (double gap : {2.0, 1.0, 0.5, 0.2, 0.05}) {
    expect_each_curve_alone({{{0, 0}, 1.0}, {{1.8 + gap, 0.1}, 0.8}},
                            fmt::format("two circles {} apart", gap),
                            {Method::robust, Method::paper});
  }
}

// Sampled more densely than epsilon asks, facing each other on one axis: the robust method once
// bridged these (two edges across the gap) into one curve, its carving refusing to cut off a
// piece of fewer than 256 triangles; each circle holds its samples' inner poles.
TEST(Separate_curves, DenselySampledCirclesFacingEachOther) {
  for (int n : {100, 200, 300}) {
    for (double gap : {0.5, 2.0}) {
      std::vector<Point<2>> samples;
      std::vector<Facet<2>> edges;
      for (const auto& [cx, r, phase] : {std::tuple{0.0, 1.0, 0.0}, {1.8 + gap, 0.8, 0.01}}) {
        const int first = static_cast<int>(samples.size());
        for (int i = 0; i < n; ++i) {
          const double a = phase + 2 * M_PI * i / n;
          samples.push_back({cx + r * std::cos(a), r * std::sin(a)});
          edges.push_back({first + i, first + (i + 1) % n});
        }
      }
      SCOPED_TRACE(fmt::format("{} samples each, {} apart", n, gap));
      const auto result = reconstruct(samples, Options{});
      EXPECT_EQ(testing::undirected(result.surface), testing::undirected(edges));
      EXPECT_EQ(result.stats.components, 2u);
    }
  }
}

TEST(Separate_curves, ThreeCirclesInARowAndInATriangle) {
  for (double gap : {1.0, 0.3, 0.1}) {
    expect_each_curve_alone({{{0, 0}, 1.0}, {{2 + gap, 0}, 1.0}, {{4 + 2 * gap, 0.2}, 1.0}},
                            fmt::format("three in a row, {} apart", gap));
    const double side = 2 + gap;
    expect_each_curve_alone(
        {{{0, 0}, 1.0}, {{side, 0}, 1.0}, {{side / 2, side * std::sqrt(3.0) / 2}, 1.0}},
        fmt::format("three in a triangle, {} apart", gap));
  }
}

TEST(Separate_curves, NestedCirclesStayTwoCurves) {
  for (double inner : {0.8, 0.5, 0.2}) {
    expect_each_curve_alone({{{0, 0}, 1.0}, {{0.05, -0.03}, inner}},
                            fmt::format("a circle of radius {} inside the unit circle", inner),
                            {Method::robust, Method::paper});
  }
  expect_each_curve_alone({{{0, 0}, 2.0}, {{-0.9, 0}, 0.6}, {{0.9, 0.1}, 0.6}},
                          "two circles inside a third");
}

// A straight stroke from `from` to `to`, its samples `spacing` apart, both ends included, added
// to the drawing as an open polyline.
void add_stroke(Drawing& drawing, Point<2> from, Point<2> to, double spacing) {
  const int n = static_cast<int>(std::ceil(std::hypot(to[0] - from[0], to[1] - from[1]) / spacing));
  const int first = static_cast<int>(drawing.samples.size());
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    drawing.samples.push_back({from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])});
    if (i > 0) drawing.edges.push_back({first + i - 1, first + i});
  }
}

// Open strokes near a closed outline keep their ends, whichever kind the samples are left to
// choose: beside it down to less than two spacings away, pointing at it, inside it, and a face
// (an outline, two eyes, an open smile). Each stroke is sampled as the outline is.
TEST(Separate_curves, OpenStrokesNearAnOutlineKeepTheirEnds) {
  struct Case {
    const char* name;
    std::vector<std::pair<Point<2>, Point<2>>> strokes;
    std::vector<Circle> eyes;
  };
  const double spacing = 2 * M_PI / 200;  // the unit circle's, with 200 samples
  const std::vector<Case> cases = {
      {"beside it, 0.3 away", {{{1.3, -0.5}, {1.3, 0.5}}}, {}},
      {"beside it, 0.05 away", {{{1.05, -0.5}, {1.05, 0.5}}}, {}},
      {"pointing at it, its end 0.06 away", {{{1.06, 0}, {2.06, 0}}}, {}},
      {"inside, pointing out", {{{-0.4, 0.05}, {0.9, 0.05}}}, {}},
      {"two strokes side by side", {{{1.3, -0.5}, {1.3, 0.5}}, {{1.5, -0.5}, {1.5, 0.5}}}, {}},
      {"a face", {{{-0.4, -0.4}, {0.4, -0.4}}}, {{{-0.35, 0.3}, 0.1}, {{0.35, 0.3}, 0.1}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Drawing drawing;
    for (int i = 0; i < 200; ++i) {
      const double a = 2 * M_PI * i / 200;
      drawing.samples.push_back({std::cos(a), std::sin(a)});
      drawing.edges.push_back({i, (i + 1) % 200});
    }
    for (const Circle& eye : c.eyes) {
      const int first = static_cast<int>(drawing.samples.size());
      const int n = static_cast<int>(std::ceil(2 * M_PI * eye.radius / spacing));
      for (int i = 0; i < n; ++i) {
        const double a = 0.2 + 2 * M_PI * i / n;
        drawing.samples.push_back(
            {eye.center[0] + eye.radius * std::cos(a), eye.center[1] + eye.radius * std::sin(a)});
        drawing.edges.push_back({first + i, first + (i + 1) % n});
      }
    }
    for (const auto& [from, to] : c.strokes) add_stroke(drawing, from, to, spacing);
    const auto result = reconstruct(drawing.samples, Options{});
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(drawing.edges));
    EXPECT_EQ(result.stats.boundary_loops, c.strokes.size());  // open curves
    EXPECT_EQ(result.stats.components, 1 + c.eyes.size() + c.strokes.size());
    EXPECT_EQ(result.stats.unused_samples, 0u);
  }
}

}  // namespace
}  // namespace sculpt
