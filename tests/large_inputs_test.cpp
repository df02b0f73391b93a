// SPDX-License-Identifier: GPL-3.0-or-later
// Slow (ctest label "slow", run with SCULPT_SLOW_TESTS=1 scripts/test): large inputs keep the
// guarantees the small ones have. Times are measured by `sculpt bench`, not asserted here.
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

TEST(Large_inputs, TorusOfThreeHundredThousandPointsIsClosedOfGenusOne) {
  Options options;
  options.keep_triangulations = false;
  const auto result = reconstruct(shapes::torus(300000), options);
  EXPECT_EQ(result.stats.conflicts, 0u);
  testing::expect_closed_manifold(result, 0);
}

TEST(Large_inputs, DenseCurveOfOneHundredThousandSamplesIsExact) {
  const auto truth = shapes::blob(100000);
  Options options;
  options.keep_triangulations = false;
  const auto result = reconstruct(truth.samples, options);
  EXPECT_EQ(testing::directed(result.surface), testing::directed(truth.edges));
}

}  // namespace
}  // namespace sculpt
