// SPDX-License-Identifier: GPL-3.0-or-later
// The inside test's index (methods/extraction/ray_crossings.hpp) against testing every triangle.
#include "methods/extraction/ray_crossings.hpp"

#include <gtest/gtest.h>

#include <random>

#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

bool crosses_odd_brute_force(const std::vector<Point<3>>& points,
                             const std::vector<Facet<3>>& triangles, const Point<3>& p) {
  bool odd = false;
  for (const auto& t : triangles) odd ^= ray_crosses(points, t, p);
  return odd;
}

TEST(Ray_crossings, TheIndexAnswersAsEveryTriangleDoes) {
  // A closed torus surface, points inside, outside and on its samples, and a second copy of
  // the triangles after others (an index over part of a list).
  const auto samples = shapes::example_points_3("torus");
  Options options;
  options.kind = Surface_kind::closed;
  const auto result = reconstruct(samples, options);
  const std::vector<Point<3>> points(result.sites.begin(),
                                     result.sites.begin() + result.sample_count());
  std::vector<Facet<3>> triangles = {{0, 1, 2}};
  triangles.insert(triangles.end(), result.surface.begin(), result.surface.end());
  const Ray_crossings index(points, triangles, 1, triangles.size());
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(-1.6, 1.6);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Point<3> p =
        i % 4 == 0 ? points[i % points.size()] : Point<3>{unit(random), unit(random), unit(random)};
    const bool odd = crosses_odd_brute_force(points, result.surface, p);
    inside += odd;
    ASSERT_EQ(index.odd_from(p), odd) << "point " << i;
  }
  EXPECT_GT(inside, 50);  // some of the points are inside the torus
  const Ray_crossings empty(points, triangles, 0, 0);
  EXPECT_FALSE(empty.odd_from(points[0]));
}

}  // namespace
}  // namespace sculpt
