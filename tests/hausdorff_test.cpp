// SPDX-License-Identifier: GPL-3.0-or-later
// The Hausdorff distance `sculpt compare` measures results with: zero for a mesh and itself,
// the gap between parallel copies, a lifted point inside a triangle, a scaled sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <sculpt/sculpt.hpp>

#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

TEST(Hausdorff, OfAMeshAndItselfIsZero) {
  const auto points = shapes::sphere(800);
  const auto result = reconstruct(points);
  ASSERT_FALSE(result.surface.empty());
  // Zero but for the rounding of the samples spread on the triangles.
  EXPECT_LT(hausdorff_distance(points, result.surface, points, result.surface), 1e-12);
}

TEST(Hausdorff, OfTwoParallelTrianglesIsTheirGap) {
  const std::vector<Point<3>> points = {{0, 0, 0},   {1, 0, 0},   {0, 1, 0},
                                        {0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}};
  EXPECT_NEAR(hausdorff_distance(points, {{0, 1, 2}}, points, {{3, 4, 5}}), 0.5, 1e-12);
}

TEST(Hausdorff, SeesAPointLiftedInsideATriangle) {
  // A flat triangle, and the same split in three at its centre lifted by 0.2: a tent whose apex
  // is no vertex of the flat one, and which no vertex of the flat one comes near.
  const std::vector<Point<3>> points = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {1, 1, 0.2}};
  const std::vector<Facet<3>> flat = {{0, 1, 2}}, tent = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  EXPECT_NEAR(hausdorff_distance(points, flat, points, tent), 0.2, 1e-12);
  EXPECT_NEAR(hausdorff_distance(points, tent, points, flat), 0.2, 1e-12);  // symmetric
}

TEST(Hausdorff, OfASphereAndItsScaledCopyIsTheScale) {
  const auto points = shapes::sphere(2000);
  const auto result = reconstruct(points);
  std::vector<Point<3>> larger = points;
  for (auto& p : larger) p = {1.1 * p[0], 1.1 * p[1], 1.1 * p[2]};
  // 0.1 between the spheres; the flat triangles lie inside them by at most their sagitta.
  const double distance = hausdorff_distance(points, result.surface, larger, result.surface);
  EXPECT_GT(distance, 0.1 - 1e-9);
  EXPECT_LT(distance, 0.11);
}

TEST(Hausdorff, IsInfiniteWithoutTriangles) {
  const std::vector<Point<3>> points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(std::isinf(hausdorff_distance(points, {}, points, {{0, 1, 3}})));
  EXPECT_TRUE(std::isinf(hausdorff_distance(points, {{0, 1, 2}}, points, {{0, 1, 3}})));  // flat
}

// The benchmark's denser inputs: one Loop step puts a vertex on every edge of a closed mesh
// (V + E vertices, 4 F triangles), keeps it closed and of the same genus, and moves it less than
// its own size; a mesh that is not a manifold is refused.
TEST(Loop_subdivision, PutsAVertexOnEveryEdgeOfTheSameClosedSurface) {
  const Triangle_mesh octahedron = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  const Triangle_mesh dense = loop_subdivided(octahedron);
  EXPECT_EQ(dense.points.size(), 6u + 12u);
  EXPECT_EQ(dense.triangles.size(), 4u * 8u);
  const Statistics topology = facet_topology(dense.points.size(), dense.triangles);
  EXPECT_EQ(topology.non_manifold_ridges, 0u);
  EXPECT_EQ(topology.boundary_ridges, 0u);
  EXPECT_EQ(topology.euler_characteristic, 2);
  for (const auto& p : dense.points) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    EXPECT_GT(r, 0.3);  // smoothed towards the centre, not collapsed onto it
    EXPECT_LT(r, 1.0);  // Loop's masks average: nothing moves out of the hull
  }
  const Triangle_mesh fin = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};  // three triangles on one edge
  EXPECT_THROW(loop_subdivided(fin), Input_error);
}

}  // namespace
}  // namespace sculpt
