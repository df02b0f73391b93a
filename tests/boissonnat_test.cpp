// SPDX-License-Identifier: GPL-3.0-or-later
// Boissonnat's greedy sculpting (1984): it stops when every sample is on the boundary, and its
// removals keep the boundary a polyhedron through the same samples, so it is exact where the
// hull only has to be dug into (a star, a bumpy sphere) but can never open a hole: an annulus
// stays a disc, a torus a sphere. That is the limitation the paper's poles lift.
#include <gtest/gtest.h>

#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

TEST(Boissonnat, ExactOnCurvesThatOnlyDigIntoTheHull) {
  for (const auto& [name, truth] :
       std::vector<std::pair<const char*, shapes::Sampled_curve>>{{"circle", shapes::circle(64)},
                                                                  {"star", shapes::star(200)},
                                                                  {"blob", shapes::blob(150)}}) {
    SCOPED_TRACE(name);
    const auto result = reconstruct(truth.samples, testing::with_method(Method::boissonnat));
    EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
    EXPECT_EQ(result.stats.carved_cells, result.carving.events.size());
    for (const auto& event : result.carving.events) {
      EXPECT_EQ(event.reason, Carve_reason::largest_bulge);
    }
  }
}

TEST(Boissonnat, ClosedSurfacesThroughEverySampleButNeverAHole) {
  const auto bumpy =
      reconstruct(shapes::bumpy_sphere(6000), testing::with_method(Method::boissonnat));
  EXPECT_TRUE(verdict(bumpy.stats).manifold) << verdict(bumpy.stats).line;
  EXPECT_EQ(bumpy.stats.euler_characteristic, 2);
  EXPECT_TRUE(testing::consistently_oriented_closed(bumpy.surface));
  EXPECT_GT(testing::signed_volume(bumpy.sites, bumpy.surface), 0);
  // The torus keeps a membrane across its hole: a sphere, not a torus.
  const auto torus = reconstruct(shapes::torus(4000), testing::with_method(Method::boissonnat));
  EXPECT_EQ(torus.stats.euler_characteristic, 2);
  // The annulus stays one closed curve around a disc.
  const auto annulus = reconstruct(shapes::nested_circles(120, 60).samples,
                                   testing::with_method(Method::boissonnat));
  EXPECT_EQ(annulus.stats.components, 1u);
  testing::expect_every_stage_builds(annulus);
  testing::expect_every_stage_builds(bumpy);
}

}  // namespace
}  // namespace sculpt
