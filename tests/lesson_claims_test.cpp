// SPDX-License-Identifier: GPL-3.0-or-later
// What the comparing lesson (examples/lessons/comparing.script) tells a class about each method
// on the two examples made for it (shapes/hard_parts.cpp), checked on the same samples: should a
// method change, the narration must change with it.
#include <gtest/gtest.h>

#include <sculpt/sculpt.hpp>

#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

template <class Samples>
Statistics run(const Samples& samples, Method method, Cleaning cleaning = Cleaning::automatic) {
  Options options;
  options.method = method;
  options.cleaning = cleaning;
  return reconstruct(samples, options).stats;
}

// 2D: the robust method closes the bracket; the paper's leaves samples off, the crust and the
// NN-crust branch.
TEST(ComparingLesson, TheBracketSetsTheCurveMethodsApart) {
  const auto samples = shapes::example_points_2("bracket");
  const Statistics robust = run(samples, Method::robust);
  EXPECT_EQ(robust.components, 1u);
  EXPECT_EQ(robust.non_manifold_ridges, 0u);
  EXPECT_EQ(robust.boundary_ridges, 0u);
  EXPECT_EQ(robust.unused_samples, 0u);
  EXPECT_GT(run(samples, Method::paper).unused_samples, 0u);
  EXPECT_GT(run(samples, Method::crust).non_manifold_ridges, 0u);
  EXPECT_GT(run(samples, Method::nn_crust).non_manifold_ridges, 0u);
}

// 3D: the block has genus 1. The paper's surface is torn, the co-cone and the Advancing Front
// leave holes; the robust method closes it through every sample with the block's genus: its
// hole opens whole, and at the noisy end it refuses to punch a handle through a web one sample
// thin; alpha shapes bury samples; the noise, at one end only, does not ask for cleaning, and
// cleaned by hand the surface keeps the block's genus.
TEST(ComparingLesson, TheDrilledBlockSetsTheSurfaceMethodsApart) {
  const auto samples = shapes::example_points_3("drilled-block");
  EXPECT_GT(run(samples, Method::paper).non_manifold_ridges, 0u);
  EXPECT_GT(run(samples, Method::cocone).boundary_loops, 10u);
  EXPECT_GT(run(samples, Method::advancing_front).boundary_loops, 0u);
  const Statistics robust = run(samples, Method::robust);
  EXPECT_EQ(robust.non_manifold_ridges, 0u);
  EXPECT_EQ(robust.boundary_ridges, 0u);
  EXPECT_EQ(robust.unused_samples, 0u);
  EXPECT_EQ(robust.euler_characteristic, 0);  // genus 1, the block's
  EXPECT_EQ(robust.carved_handles, 1u);       // the hole, opened whole
  EXPECT_EQ(robust.refused_handles, 1u);      // the noisy end's web, not punched through
  EXPECT_EQ(robust.thin_handles, 0u);
  EXPECT_FALSE(robust.cleaned);  // the noise at one end does not ask for it
  const Statistics alpha = run(samples, Method::alpha_shape);
  EXPECT_GT(alpha.unused_samples, 100u);
  EXPECT_GT(alpha.alpha, 0.3);  // wider than the hole (radius 0.3), which it fills
  const Statistics cleaned = run(samples, Method::robust, Cleaning::jet);
  EXPECT_TRUE(cleaned.cleaned);
  EXPECT_EQ(cleaned.non_manifold_ridges, 0u);
  EXPECT_EQ(cleaned.boundary_ridges, 0u);
  EXPECT_EQ(cleaned.euler_characteristic, 0);  // genus 1, the block's
}

}  // namespace
}  // namespace sculpt
