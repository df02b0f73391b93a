// SPDX-License-Identifier: GPL-3.0-or-later
// The power crust (Amenta, Choi & Kolluri 2001): on densely sampled closed shapes it is a closed,
// outward-facing 2-manifold of the shape's genus (closed curves running counterclockwise in 2D),
// through vertices of its own near the samples, not through the samples, and more of them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "core2d/traits_2.hpp"
#include "core3d/traits_3.hpp"
#include "methods/power_crust/power_crust_method.hpp"
#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

template <int D>
double squared_distance(const Point<D>& a, const Point<D>& b) {
  double sum = 0;
  for (int k = 0; k < D; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return sum;
}

// The largest distance from a point of `from` to its nearest point of `to` (brute force).
template <int D>
double farthest_nearest(const std::vector<Point<D>>& from, const std::vector<Point<D>>& to) {
  double worst = 0;
  for (const auto& p : from) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& q : to) nearest = std::min(nearest, squared_distance<D>(p, q));
    worst = std::max(worst, nearest);
  }
  return std::sqrt(worst);
}

// The power diagram stage inserts the poles one at a time (to report progress) as CGAL's range
// insertion does: the same regular triangulation, its vertices and cells (faces) in the same
// order, each vertex knowing its pole. (The poles of a shape's samples are nearly cospherical:
// CGAL falls back on exact predicates there, and the noisy sphere has more such ties.)
template <class Traits>
void expect_power_diagram_in_cgals_order(const std::vector<Point<Traits::dimension>>& samples) {
  constexpr int D = Traits::dimension;
  using Kernel = typename Traits::Kernel;
  using Regular = power_crust_detail::Regular<D, Kernel>;
  const auto result = reconstruct(samples, testing::with_method(Method::power_crust));
  EXPECT_GT(result.poles.poles.size(), 100u);
  const testing::Silent_clock silent;
  const Stage_clock& clock = silent.clock;
  Regular stepwise;
  power_crust_detail::build_power_diagram<Kernel>(stepwise, result, clock);
  const auto weighted = power_crust_detail::weighted_poles<Kernel>(result);
  const Regular at_once(weighted.begin(), weighted.end());
  std::vector<std::pair<typename Regular::Weighted_point, int>> ours, cgals;
  for (auto v : stepwise.finite_vertex_handles()) {
    ours.push_back({v->point(), v->info()});
    EXPECT_EQ(weighted[v->info()].first, v->point()) << "a vertex knows its pole";
  }
  for (auto v : at_once.finite_vertex_handles()) cgals.push_back({v->point(), v->info()});
  EXPECT_GT(ours.size(), weighted.size() / 2);
  EXPECT_EQ(ours, cgals);
  EXPECT_EQ(testing::cells_as_vertex_infos<D>(stepwise),
            testing::cells_as_vertex_infos<D>(at_once));
}

TEST(PowerCrust, ThePowerDiagramStageInsertsInCgalsOrder) {
  expect_power_diagram_in_cgals_order<Traits_3>(shapes::bumpy_sphere(3000));
  expect_power_diagram_in_cgals_order<Traits_3>(shapes::torus(2000));
  expect_power_diagram_in_cgals_order<Traits_3>(shapes::noisy_sphere(3000, 0.3));
  expect_power_diagram_in_cgals_order<Traits_2>(shapes::star(300).samples);
}

TEST(PowerCrust, ClosedOutwardManifoldsOfTheShapesGenus) {
  for (const auto& [name, samples, genus] :
       std::vector<std::tuple<const char*, std::vector<Point<3>>, int>>{
           {"sphere", shapes::sphere(2000), 0},
           {"torus", shapes::torus(4000), 1},
           {"bumpy sphere", shapes::bumpy_sphere(6000), 0}}) {
    SCOPED_TRACE(name);
    const auto result = reconstruct(samples, testing::with_method(Method::power_crust));
    const Verdict v = verdict(result.stats);
    EXPECT_TRUE(v.manifold) << v.line;
    EXPECT_EQ(result.stats.components, 1u);
    EXPECT_EQ(result.stats.euler_characteristic, 2 - 2 * genus);
    EXPECT_TRUE(testing::consistently_oriented_closed(result.surface));
    EXPECT_GT(testing::signed_volume(result.surface_vertices, result.surface), 0);
    EXPECT_EQ(result.stats.unbounded_power_faces, 0u);
  }
}

TEST(PowerCrust, PassesNearTheSamplesThroughVerticesOfItsOwn) {
  const auto samples = shapes::torus(4000);
  const auto result = reconstruct(samples, testing::with_method(Method::power_crust));
  EXPECT_FALSE(result.interpolates());
  EXPECT_EQ(result.stats.surface_vertices, result.surface_vertices.size());
  // More vertices than samples (ACK 2001 report several times more).
  EXPECT_GT(result.surface_vertices.size(), 2 * samples.size());
  // Not one of them is a sample, yet every sample is close to one and every one to a sample.
  std::set<Point<3>> sample_set(samples.begin(), samples.end());
  for (const auto& v : result.surface_vertices) ASSERT_FALSE(sample_set.count(v));
  const double size = testing::box_diagonal<3>(samples);
  EXPECT_LT(farthest_nearest<3>(samples, result.surface_vertices), 0.02 * size);
  EXPECT_LT(farthest_nearest<3>(result.surface_vertices, samples), 0.05 * size);
  EXPECT_NE(verdict(result.stats).line.find("vertices of its own"), std::string::npos);
}

TEST(PowerCrust, ClosedCurvesCounterclockwiseAroundWhatTheyBound) {
  for (const auto& [name, truth, curves] :
       std::vector<std::tuple<const char*, shapes::Sampled_curve, std::size_t>>{
           {"circle", shapes::circle(64), 1},
           {"star", shapes::star(200), 1},
           {"blob", shapes::blob(150), 1},
           {"nested circles", shapes::nested_circles(120, 60), 2}}) {
    SCOPED_TRACE(name);
    const auto result = reconstruct(truth.samples, testing::with_method(Method::power_crust));
    const Verdict v = verdict(result.stats);
    EXPECT_TRUE(v.manifold) << v.line;
    EXPECT_EQ(result.stats.components, curves);
    // Every vertex starts one edge and ends one: closed and consistently directed.
    std::map<int, int> starts, ends;
    for (const auto& e : result.surface) ++starts[e[0]], ++ends[e[1]];
    for (const auto& [vertex, count] : starts) EXPECT_EQ(count, 1);
    EXPECT_EQ(starts.size(), ends.size());
    // The enclosed area, by the shoelace formula: positive when counterclockwise, and close to
    // the true polygon's (an annulus' is the outer disc's less the inner's).
    const auto area = [](const std::vector<Point<2>>& points, const std::vector<Facet<2>>& edges) {
      double twice = 0;
      for (const auto& e : edges) {
        twice += points[e[0]][0] * points[e[1]][1] - points[e[1]][0] * points[e[0]][1];
      }
      return twice / 2;
    };
    const double truth_area = area(truth.samples, truth.edges);
    EXPECT_GT(truth_area, 0);
    EXPECT_NEAR(area(result.surface_vertices, result.surface), truth_area, 0.05 * truth_area);
  }
}

TEST(PowerCrust, EveryStageBuildsAndItsFilesHoldItsOwnVertices) {
  const auto truth = shapes::star(200);
  const auto curve = reconstruct(truth.samples, testing::with_method(Method::power_crust));
  testing::expect_every_stage_builds(curve);
  const auto surface = reconstruct(shapes::sphere(500), testing::with_method(Method::power_crust));
  testing::expect_every_stage_builds(surface);
  // Labelled by the same confidence labelling as the robust method.
  const auto robust = reconstruct(truth.samples);
  EXPECT_EQ(curve.propagation.labels, robust.propagation.labels);
}

}  // namespace
}  // namespace sculpt
