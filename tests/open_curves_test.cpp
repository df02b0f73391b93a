// SPDX-License-Identifier: GPL-3.0-or-later
// 2D curves that end: the robust method's bordered rule (src/methods/robust/open_curves.hpp)
// gives every stroke as one open polyline through its samples, with no chord between its ends
// and no branch point, and keeps closed curves closed.
#include "methods/robust/open_curves.hpp"

#include <cmath>
#include <map>

#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

struct Open_case {
  const char* name;
  shapes::Sampled_curve truth;
  std::size_t strokes;
};

std::vector<Open_case> open_cases() {
  return {{"wavy arc 90", shapes::wavy_arc(90), 1},     {"wavy arc 180", shapes::wavy_arc(180), 1},
          {"wavy arc 270", shapes::wavy_arc(270), 1},   {"wavy arc 340", shapes::wavy_arc(340), 1},
          {"spiral 2.5 turns", shapes::spiral(2.5), 1}, {"two strokes", shapes::two_strokes(), 2},
          {"built-in arc", shapes::open_arc(60), 1}};
}

Options robust_bordered() {
  Options options;
  options.method = Method::robust;
  options.kind = Surface_kind::bordered;
  return options;
}

// Each piece is a chain: no vertex starts (or ends) two of its edges.
bool chained(const std::vector<Facet<2>>& edges) {
  std::map<int, int> starts, ends;
  for (const auto& e : edges) {
    if (++starts[e[0]] > 1 || ++ends[e[1]] > 1) return false;
  }
  return true;
}

TEST(Open_curves, EveryStrokeIsOneOpenPolylineThroughItsSamples) {
  for (const auto& c : open_cases()) {
    SCOPED_TRACE(c.name);
    const auto result = reconstruct(c.truth.samples, robust_bordered());
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(c.truth.edges));
    EXPECT_EQ(result.stats.boundary_ridges, 2 * c.strokes);  // two ends a stroke
    EXPECT_EQ(result.stats.boundary_loops, c.strokes);       // open curves
    EXPECT_EQ(result.stats.components, c.strokes);
    EXPECT_EQ(result.stats.non_manifold_ridges, 0u);
    EXPECT_EQ(result.stats.unused_samples, 0u);
    EXPECT_TRUE(chained(result.surface)) << "edges do not run the same way along the stroke";
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
  }
}

TEST(Open_curves, NoTinyLoopCloses) {
  // Three samples close together beside two strokes: noise, not a closed curve. They stay one
  // open piece of two edges instead of a triangle.
  auto samples = shapes::two_strokes().samples;
  for (const Point<2>& p : {Point<2>{3.0, 0.0}, Point<2>{3.04, 0.0}, Point<2>{3.02, 0.035}}) {
    samples.push_back(p);
  }
  const auto result = reconstruct(samples, robust_bordered());
  EXPECT_EQ(result.stats.boundary_loops, 3u) << "open curves";
  EXPECT_EQ(result.stats.components, 3u);
  EXPECT_EQ(result.stats.unused_samples, 0u);
  EXPECT_EQ(result.stats.non_manifold_ridges, 0u);
}

TEST(Open_curves, ClosedCurvesStayClosed) {
  for (const auto& [name, truth] : std::vector<std::pair<const char*, shapes::Sampled_curve>>{
           {"star", shapes::star(200)},
           {"blob", shapes::blob(150)},
           {"nested circles", shapes::nested_circles(120, 60)},
           {"non-uniform ellipse", shapes::nonuniform_ellipse(200)}}) {
    SCOPED_TRACE(name);
    const auto result = reconstruct(truth.samples, robust_bordered());
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
    EXPECT_EQ(result.stats.boundary_ridges, 0u);
  }
}

// The rule's one number, end_gap_ratio, sits between what the curves measure: along a stroke an
// edge is at most a little longer than the spacing at its ends; across an opening, the nearest
// sample beyond an end is many spacings away. The margins are printed.
TEST(Open_curves, TheEndGapRatioSeparatesStrokesFromOpenings) {
  const auto distance = [](const Point<2>& a, const Point<2>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
  };
  std::vector<Open_case> cases = open_cases();
  cases.push_back({"star", shapes::star(200), 0});
  cases.push_back({"non-uniform ellipse", shapes::nonuniform_ellipse(200), 0});
  double longest_edge = 0, shortest_opening = HUGE_VAL;
  for (const auto& c : cases) {
    const auto& s = c.truth.samples;
    const int n = static_cast<int>(s.size());
    std::vector<double> spacing(n, HUGE_VAL);
    std::vector<int> nearest(n, -1);
    for (int p = 0; p < n; ++p) {
      for (int q = 0; q < n; ++q) {
        if (q != p && distance(s[p], s[q]) < spacing[p]) {
          spacing[p] = distance(s[p], s[q]);
          nearest[p] = q;
        }
      }
    }
    std::vector<int> degree(n, 0);
    for (const auto& e : c.truth.edges) {
      ++degree[e[0]];
      ++degree[e[1]];
      longest_edge = std::max(longest_edge,
                              distance(s[e[0]], s[e[1]]) / std::max(spacing[e[0]], spacing[e[1]]));
    }
    for (int p = 0; p < n; ++p) {
      if (degree[p] != 1) continue;  // an end: the nearest sample on the far side of its neighbour
      const int q = nearest[p];
      for (int r = 0; r < n; ++r) {
        const double dot =
            (s[r][0] - s[p][0]) * (s[q][0] - s[p][0]) + (s[r][1] - s[p][1]) * (s[q][1] - s[p][1]);
        if (r == p || dot >= 0) continue;
        shortest_opening =
            std::min(shortest_opening, distance(s[p], s[r]) / std::max(spacing[p], spacing[r]));
      }
    }
  }
  std::cout << "edge / spacing along strokes: at most " << longest_edge
            << "; across openings: at least " << shortest_opening << '\n';
  EXPECT_LT(longest_edge, end_gap_ratio);
  EXPECT_GT(shortest_opening, end_gap_ratio);
}

TEST(Open_curves, ThePaperMethodKeepsItsLiteralRule) {
  // The figures need the paper's bordered rule as published: on the arc it keeps the chord.
  Options paper = robust_bordered();
  paper.method = Method::paper;
  const auto arc = shapes::open_arc(60);
  const auto result = reconstruct(arc.samples, paper);
  EXPECT_NE(testing::undirected(result.surface), testing::undirected(arc.edges));
}

// A stroke drawn in the viewer becomes samples evenly spaced along it, its two ends included,
// and the robust bordered rule gives it back as one open polyline.
TEST(Open_curves, ADrawnStrokeBecomesEvenlySpacedSamplesThatGiveItBack) {
  const std::vector<Point<2>> stroke = {{0, 0}, {1, 0}, {1, 0}, {1.5, 0.5}, {2, 0.3}};
  const double spacing = 0.07;
  const auto samples = shapes::resample_polyline(stroke, spacing);
  ASSERT_GE(samples.size(), 3u);
  EXPECT_EQ(samples.front(), stroke.front());
  EXPECT_EQ(samples.back(), stroke.back());
  double length = 0;
  for (std::size_t i = 1; i < stroke.size(); ++i)
    length += std::hypot(stroke[i][0] - stroke[i - 1][0], stroke[i][1] - stroke[i - 1][1]);
  EXPECT_NEAR(double(samples.size() - 1), length / spacing, 1.0);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double gap =
        std::hypot(samples[i][0] - samples[i - 1][0], samples[i][1] - samples[i - 1][1]);
    // Straight runs keep the spacing; across a corner the chord is shorter; the end may be
    // up to one and a half spacings from the last.
    EXPECT_LE(gap, 1.5 * spacing + 1e-12) << i;
    EXPECT_GT(gap, 0.3 * spacing) << i;
  }
  const auto result = reconstruct(samples, robust_bordered());
  EXPECT_EQ(result.stats.components, 1u);
  EXPECT_EQ(result.stats.boundary_ridges, 2u);  // two end points
  EXPECT_EQ(result.surface.size(), samples.size() - 1);
  EXPECT_TRUE(chained(result.surface));
  // A spacing too fine for the stroke is widened to at most `most` samples, evenly.
  const auto capped = shapes::resample_polyline(stroke, 1e-300, 500);
  EXPECT_EQ(capped.size(), 500u);
  EXPECT_EQ(capped.back(), stroke.back());
  // Nothing to sample: no stroke, or no spacing.
  EXPECT_TRUE(shapes::resample_polyline({}, spacing).empty());
  EXPECT_TRUE(shapes::resample_polyline(stroke, 0).empty());
}

}  // namespace
}  // namespace sculpt
