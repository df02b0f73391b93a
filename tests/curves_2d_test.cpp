// 2D: sampled closed curves come back as exactly the polygon through consecutive samples,
// oriented counterclockwise around the region they bound.
#include <cmath>

#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

void expect_exact_polygon(const shapes::Sampled_curve& truth, const Options& options = {}) {
  const auto result = reconstruct(truth.samples, options);
  EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
  EXPECT_EQ(testing::directed(result.surface), testing::directed(truth.edges))
      << "the curve is not oriented with its region on the left";
  EXPECT_EQ(result.stats.conflicts, 0u);
  EXPECT_EQ(result.stats.unlabelled_poles, 0u);
  EXPECT_EQ(result.stats.unused_samples, 0u);
  EXPECT_EQ(result.stats.boundary_ridges, 0u);
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
  // Without --bordered the same open samples come back closed: the paper's Fig. 8 contrast.
  const auto arc = shapes::open_arc(60);
  const auto result = reconstruct(arc.samples);
  EXPECT_EQ(result.stats.boundary_ridges, 0u);
  EXPECT_EQ(result.stats.facets, 60u);
}

}  // namespace
}  // namespace sculpt
