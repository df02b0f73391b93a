// SPDX-License-Identifier: GPL-3.0-or-later
// 2D: sampled closed curves come back as exactly the polygon through consecutive samples,
// oriented counterclockwise around the region they bound.
#include <cmath>

#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

bool exact_polygon(const shapes::Sampled_curve& truth, const Options& options) {
  const auto result = reconstruct(truth.samples, options);
  return testing::undirected(result.surface) == testing::undirected(truth.edges);
}

void expect_exact_polygon(const shapes::Sampled_curve& truth, Options options = {}) {
  for (Method method : {Method::paper, Method::robust}) {
    SCOPED_TRACE(to_string(method));
    options.method = method;
    const auto result = reconstruct(truth.samples, options);
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
    EXPECT_EQ(testing::directed(result.surface), testing::directed(truth.edges))
        << "the curve is not oriented with its region on the left";
    EXPECT_EQ(result.stats.conflicts, 0u);
    EXPECT_EQ(result.stats.unlabelled_poles, 0u);
    EXPECT_EQ(result.stats.unused_samples, 0u);
    EXPECT_EQ(result.stats.boundary_ridges, 0u);
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
  }
}

// A polygon sampled uniformly by arc length, starting at its first corner.
shapes::Sampled_curve sampled_polygon(const std::vector<Point<2>>& corners, int samples) {
  std::vector<double> lengths;
  double perimeter = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    lengths.push_back(std::hypot(b[0] - a[0], b[1] - a[1]));
    perimeter += lengths.back();
  }
  shapes::Sampled_curve curve;
  for (int k = 0; k < samples; ++k) {
    double at = perimeter * k / samples;
    std::size_t side = 0;
    while (at > lengths[side]) at -= lengths[side++];
    const auto& a = corners[side];
    const auto& b = corners[(side + 1) % corners.size()];
    const double t = at / lengths[side];
    curve.samples.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    curve.edges.push_back({k, (k + 1) % samples});
  }
  return curve;
}

// Sparse five-armed stars and a concave right-angled corner, where a breadth-first labelling can
// cut valleys off.
TEST(Curves_2d, RobustMethodIsExactOnSparseStars) {
  Options robust;
  robust.method = Method::robust;
  for (int n : {30, 40, 50}) {
    SCOPED_TRACE(n);
    const auto truth = shapes::star(n);
    EXPECT_TRUE(exact_polygon(truth, robust));
    EXPECT_TRUE(verdict(reconstruct(truth.samples, robust).stats).manifold);
  }
}

TEST(Curves_2d, RobustMethodIsExactAtAConcaveRightAngle) {
  Options robust;
  robust.method = Method::robust;
  const auto truth = sampled_polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 48);
  EXPECT_TRUE(exact_polygon(truth, robust));
}

TEST(Curves_2d, CircleWithCocircularSamples) {
  expect_exact_polygon(shapes::circle(64));
}

TEST(Curves_2d, FiveArmedStar) {
  expect_exact_polygon(shapes::star(200));
}

TEST(Curves_2d, Blob) {
  expect_exact_polygon(shapes::blob(150));
}

TEST(Curves_2d, TwoNestedCurvesBoundAnAnnulus) {
  const auto truth = shapes::nested_circles(120, 60);
  expect_exact_polygon(truth);
  EXPECT_EQ(reconstruct(truth.samples).stats.components, 2u);
}

TEST(Curves_2d, NonUniformSamplingNineToOne) {
  const auto truth = shapes::nonuniform_ellipse(200, 9.0);
  // The sampling really is 9:1: compare the longest and shortest edge.
  double shortest = 1e9, longest = 0;
  for (const auto& e : truth.edges) {
    const auto& a = truth.samples[e[0]];
    const auto& b = truth.samples[e[1]];
    const double length = std::hypot(a[0] - b[0], a[1] - b[1]);
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
  }
  EXPECT_GT(longest / shortest, 6.0);
  expect_exact_polygon(truth);
}

TEST(Curves_2d, BothRulesAgreeOnCleanInput) {
  Options extraction;
  extraction.rule = Surface_rule::extraction;
  expect_exact_polygon(shapes::star(200), extraction);
}

TEST(Curves_2d, OpenCurveInBorderedMode) {
  // A sine wave: an open curve whose two ends must stay apart.
  shapes::Sampled_curve truth;
  const int n = 80;
  for (int i = 0; i < n; ++i) {
    const double x = double(i) / (n - 1);
    truth.samples.push_back({x, 0.3 * std::sin(2 * 3.14159265358979 * x)});
    if (i > 0) truth.edges.push_back({i - 1, i});
  }
  Options options;
  options.kind = Surface_kind::bordered;
  const auto result = reconstruct(truth.samples, options);
  EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
  EXPECT_EQ(result.stats.boundary_ridges, 2u);  // the two end points
  EXPECT_EQ(result.stats.boundary_loops, 1u);   // one open curve
}

TEST(Curves_2d, ClosedModeClosesAnOpenCurve) {
  // As closed, the same open samples come back closed: the paper's Fig. 8 contrast.
  const auto arc = shapes::open_arc(60);
  Options closed;
  closed.kind = Surface_kind::closed;
  const auto result = reconstruct(arc.samples, closed);
  EXPECT_EQ(result.stats.boundary_ridges, 0u);
  EXPECT_EQ(result.stats.facets, 60u);
}

}  // namespace
}  // namespace sculpt
