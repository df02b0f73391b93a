// SPDX-License-Identifier: GPL-3.0-or-later
// The co-cone's undersampling detection (Dey & Giesen 2001) and the tight co-cone (Dey &
// Goswami 2003): on dense samples of smooth closed shapes nothing is undersampled and both give
// the same closed surface (the tight co-cone's solid bounded by it); where a cap of samples is
// missing, the co-cone marks the samples around the opening and leaves a hole, and the tight
// co-cone closes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

// A unit sphere of 3000 samples without those above z = 0.3: an opening of radius 0.95, wider
// than the local feature size (undersampling.hpp says why a narrower one is not found).
std::vector<Point<3>> sphere_with_an_opening() {
  std::vector<Point<3>> kept;
  for (const auto& p : shapes::sphere(3000)) {
    if (p[2] < 0.3) kept.push_back(p);
  }
  return kept;
}

TEST(Cocones, NothingUndersampledOnDenseSmoothShapesAndBothCoconesAgree) {
  for (const auto& [name, samples] : std::vector<std::pair<const char*, std::vector<Point<3>>>>{
           {"sphere", shapes::sphere(2000)},
           {"torus", shapes::torus(4000)},
           {"bumpy sphere", shapes::bumpy_sphere(6000)}}) {
    SCOPED_TRACE(name);
    const auto cocone = reconstruct(samples, testing::with_method(Method::cocone));
    const auto tight = reconstruct(samples, testing::with_method(Method::tight_cocone));
    EXPECT_EQ(cocone.stats.undersampled_samples, 0u);
    EXPECT_EQ(tight.stats.samples_without_umbrella, 0u);
    EXPECT_TRUE(verdict(tight.stats).manifold) << verdict(tight.stats).line;
    EXPECT_EQ(testing::unordered(tight.surface), testing::unordered(cocone.surface));
    // The surface is the skin of the cells left, facing out of them.
    EXPECT_GT(tight.solid.size(), 0u);
    EXPECT_TRUE(testing::consistently_oriented_closed(tight.surface));
    EXPECT_GT(testing::signed_volume(tight.sites, tight.surface), 0);
  }
}

TEST(Cocones, TheSamplesAroundAnOpeningAreUndersampledAndLeaveAHole) {
  const auto samples = sphere_with_an_opening();
  const auto cocone = reconstruct(samples, testing::with_method(Method::cocone));
  ASSERT_GT(cocone.stats.undersampled_samples, 0u);
  EXPECT_EQ(cocone.stats.undersampled_samples, cocone.candidates.undersampled.size());
  // Marked at the opening, not elsewhere: every undersampled sample within two spacings of its
  // rim (the samples are about 0.065 apart).
  for (int s : cocone.candidates.undersampled) {
    EXPECT_GT(samples[s][2], 0.3 - 0.13) << "sample " << s << " far from the opening";
  }
  EXPECT_GE(cocone.stats.boundary_loops, 1u) << verdict(cocone.stats).line;
  EXPECT_FALSE(verdict(cocone.stats).manifold);
}

TEST(Cocones, TheTightCoconeClosesTheOpening) {
  const auto samples = sphere_with_an_opening();
  const auto tight = reconstruct(samples, testing::with_method(Method::tight_cocone));
  EXPECT_EQ(tight.stats.boundary_ridges, 0u) << verdict(tight.stats).line;
  EXPECT_EQ(tight.stats.unused_samples, 0u) << verdict(tight.stats).line;
  EXPECT_GT(tight.stats.samples_without_umbrella, 0u);
  EXPECT_EQ(tight.stats.components, 1u);
  testing::expect_every_stage_builds(tight);
}

TEST(Cocones, TheTightCoconeRefusesCurvesInOneLine) {
  try {
    reconstruct(shapes::circle(64).samples, testing::with_method(Method::tight_cocone));
    ADD_FAILURE() << "the tight co-cone reconstructs surfaces only";
  } catch (const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("surfaces (3D points) only"), std::string::npos);
  }
}

}  // namespace
}  // namespace sculpt
