// SPDX-License-Identifier: GPL-3.0-or-later
// The verdict's one line says all it knows: the handles refused and suspect whatever else it
// says, a bordered result's border loops even when it is not a manifold, the genus of a closed
// result in several pieces, noise that could not be measured as such; and refusals name points
// by their place counted from 1.
#include <gtest/gtest.h>

#include <sculpt/sculpt.hpp>
#include <string>

#include "core/point_names.hpp"

namespace sculpt {
namespace {

Statistics closed_surface(long euler, std::size_t components) {
  Statistics s;
  s.dimension = 3;
  s.kind = Surface_kind::closed;
  s.samples = 100;
  s.facets = 196;
  s.components = components;
  s.euler_characteristic = euler;
  return s;
}

bool says(const Statistics& s, const std::string& words) {
  return verdict(s).line.find(words) != std::string::npos;
}

TEST(Verdict, HandlesRefusedAndSuspectAreToldOnEveryResult) {
  Statistics s = closed_surface(2, 1);
  s.refused_handles = 13;
  s.thin_handles = 1;
  EXPECT_TRUE(verdict(s).manifold);
  EXPECT_TRUE(says(s, "genus 0")) << verdict(s).line;
  EXPECT_TRUE(says(s, "13 handles refused: a web kept")) << verdict(s).line;
  EXPECT_TRUE(says(s, "1 handle suspect")) << verdict(s).line;
  s.unused_samples = 1;  // not a manifold any more: the handles are still told
  EXPECT_FALSE(verdict(s).manifold);
  EXPECT_TRUE(says(s, "NOT a closed 2-manifold: 1 sample not on it")) << verdict(s).line;
  EXPECT_TRUE(says(s, "13 handles refused")) << verdict(s).line;
  EXPECT_TRUE(says(s, "1 handle suspect")) << verdict(s).line;
}

TEST(Verdict, ABorderedResultThatIsNotAManifoldTellsItsLoops) {
  Statistics s = closed_surface(-11, 1);
  s.kind = Surface_kind::bordered;
  s.boundary_loops = 7;
  s.boundary_ridges = 194;
  s.non_manifold_vertices = 4;
  EXPECT_TRUE(says(s,
                   "NOT a bordered 2-manifold: 4 non-manifold vertices; 7 border loops, 1 "
                   "component, Euler characteristic -11"))
      << verdict(s).line;
}

TEST(Verdict, TheGenusOfSeveralPiecesIsTheirSum) {
  EXPECT_TRUE(says(closed_surface(4, 2), "closed 2-manifold of genus 0 in all: 2 components"))
      << verdict(closed_surface(4, 2)).line;
  EXPECT_TRUE(says(closed_surface(0, 2), "of genus 2 in all"))
      << verdict(closed_surface(0, 2)).line;
  EXPECT_TRUE(says(closed_surface(0, 1), "of genus 1: 1 component"));
}

TEST(Verdict, NoiseThatCouldNotBeMeasuredIsSaidSo) {
  Statistics s = closed_surface(2, 1);
  s.cleaned = true;
  s.smoothed = true;
  s.noise = 0.25;
  s.noise_after = -1;
  s.cleaning_shift = 0.96;
  EXPECT_TRUE(says(s, "noise 0.25 of their spacing, not measured after")) << verdict(s).line;
  EXPECT_FALSE(says(s, "-1")) << verdict(s).line;
  s.noise = -1;
  s.noise_after = 0.02;
  EXPECT_TRUE(says(s, "noise not measured, 0.02 after")) << verdict(s).line;
}

TEST(Verdict, OutliersRemovedAreNotOnTheSurface) {
  Statistics s = closed_surface(2, 1);
  s.cleaned = true;
  s.outliers_sought = true;
  s.outliers_removed = 1;
  EXPECT_TRUE(says(s, "; through the samples cleaned first (1 outlier removed, not on it)"))
      << verdict(s).line;
  s.outliers_removed = 0;
  EXPECT_TRUE(says(s, "cleaned first (no outlier found)")) << verdict(s).line;
  s.outliers_removed = 12;
  s.smoothed = true;
  s.noise = 0.5;
  s.noise_after = 0.02;
  s.cleaning_shift = 0.3;
  EXPECT_TRUE(says(s,
                   "cleaned first (12 outliers removed, not on it; smoothed: noise 0.50 of "
                   "their spacing, 0.02 after; moved 0.30 of the spacing on average)"))
      << verdict(s).line;
  // Sought and not found, beside the smoothing; not sought, nothing said of them.
  s.outliers_removed = 0;
  EXPECT_TRUE(says(s, "cleaned first (no outlier found; smoothed: noise 0.50")) << verdict(s).line;
  s.outliers_sought = false;
  EXPECT_TRUE(says(s, "cleaned first (smoothed: noise 0.50")) << verdict(s).line;
}

TEST(Point_names, CountedFromOneAsOrdinals) {
  EXPECT_EQ(ordinal_point(0), "the 1st point");
  EXPECT_EQ(ordinal_point(1), "the 2nd point");
  EXPECT_EQ(ordinal_point(2), "the 3rd point");
  EXPECT_EQ(ordinal_point(3), "the 4th point");
  EXPECT_EQ(ordinal_point(10), "the 11th point");
  EXPECT_EQ(ordinal_point(11), "the 12th point");
  EXPECT_EQ(ordinal_point(12), "the 13th point");
  EXPECT_EQ(ordinal_point(20), "the 21st point");
  EXPECT_EQ(ordinal_point(110), "the 111th point");
  EXPECT_EQ(ordinal_point(121), "the 122nd point");
  EXPECT_EQ(ordinal_point(795), "the 796th point");
}

}  // namespace
}  // namespace sculpt
