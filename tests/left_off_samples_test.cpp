// SPDX-License-Identifier: GPL-3.0-or-later
// Mending a bordered surface's border (methods/robust/left_off_samples.hpp): samples left off
// attached, sharp notches closed, each only where a triangle may be added.
#include "methods/robust/left_off_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace sculpt {
namespace {

// A flat sheet: the unit grid over [0, 3] x [0, 3], two triangles a cell, facing up (+z).
struct Sheet {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles;
};

Sheet grid_sheet() {
  Sheet sheet;
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 3; ++i) sheet.points.push_back({double(i), double(j), 0});
  }
  const auto at = [](int i, int j) { return 4 * j + i; };
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      sheet.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      sheet.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return sheet;
}

double facing_up(const std::vector<Point<3>>& p, const Facet<3>& f) {
  return (p[f[1]][0] - p[f[0]][0]) * (p[f[2]][1] - p[f[0]][1]) -
         (p[f[1]][1] - p[f[0]][1]) * (p[f[2]][0] - p[f[0]][0]);
}

const auto anything_may_be_added = [](const Facet<3>&) { return false; };

TEST(Left_off_samples, ASampleBesideTheBorderIsAttachedToTheNearestEdge) {
  Sheet sheet = grid_sheet();
  const int left_off = static_cast<int>(sheet.points.size());
  sheet.points.push_back({1.5, -0.4, 0});  // below the border edge (1, 0) - (2, 0)
  const std::size_t before = sheet.triangles.size();
  EXPECT_EQ(attach_left_off_samples(sheet.points, sheet.triangles, anything_may_be_added), 1u);
  ASSERT_EQ(sheet.triangles.size(), before + 1);
  const Facet<3>& added = sheet.triangles.back();
  EXPECT_EQ(added[2], left_off);
  EXPECT_EQ(std::min(added[0], added[1]), 1);
  EXPECT_EQ(std::max(added[0], added[1]), 2);
  EXPECT_GT(facing_up(sheet.points, added), 0);
}

TEST(Left_off_samples, NoTriangleWhereNoneMayBeAddedNorOneFoldedBack) {
  Sheet sheet = grid_sheet();
  sheet.points.push_back({1.5, -4, 0});  // far below: its triangle would be over an opening
  const auto wide = [&](const Facet<3>& f) { return facet_circumradius<3>(sheet.points, f) > 1.5; };
  EXPECT_EQ(attach_left_off_samples(sheet.points, sheet.triangles, wide), 0u);
  // Above the sheet's middle, off the border: every border triangle to it folds back over it.
  Sheet above = grid_sheet();
  above.points.push_back({1.5, 1.5, 0.1});
  EXPECT_EQ(attach_left_off_samples(above.points, above.triangles, anything_may_be_added), 0u);
}

TEST(Left_off_samples, ARowOfSamplesIsAttachedNearestFirst) {
  // Three samples in a line away from the border edge (1, 0) - (2, 0): the nearest goes on the
  // edge, the next on the edges it made, and so on, never a far one over a near one.
  Sheet sheet = grid_sheet();
  for (double y : {-0.5, -1.0, -1.5}) sheet.points.push_back({1.5, y, 0});
  EXPECT_EQ(attach_left_off_samples(sheet.points, sheet.triangles, anything_may_be_added), 3u);
  const std::size_t first = sheet.triangles.size() - 3;
  EXPECT_EQ(sheet.triangles[first][2], 16);
  for (std::size_t t = first; t < sheet.triangles.size(); ++t) {
    EXPECT_GT(facing_up(sheet.points, sheet.triangles[t]), 0);
  }
}

TEST(Left_off_samples, OneTriangleARoundAtABorderVertex) {
  // Below the border edges (0, 0) - (1, 0) and (1, 0) - (2, 0), one sample each: both fit, but
  // their triangles share the vertex (1, 0) and could overlap, so they go on in two rounds.
  Sheet sheet = grid_sheet();
  sheet.points.push_back({0.5, -0.4, 0});  // 16
  sheet.points.push_back({1.5, -0.4, 0});  // 17
  EXPECT_EQ(attach_left_off_samples(sheet.points, sheet.triangles, anything_may_be_added), 2u);
  const std::set<Facet<3>> added(sheet.triangles.end() - 2, sheet.triangles.end());
  EXPECT_EQ(added, (std::set<Facet<3>>{{1, 0, 16}, {2, 1, 17}}));
}

TEST(Left_off_samples, ASharpNotchBetweenTwoSpikesIsClosed) {
  // Two spikes on the border edges (0, 0) - (1, 0) and (1, 0) - (2, 0), leaning towards each
  // other: the border turns at (1, 0) by about 30 degrees between their tips.
  Sheet sheet = grid_sheet();
  sheet.points.push_back({0.8, -2, 0});  // 16
  sheet.points.push_back({1.2, -2, 0});  // 17
  sheet.triangles.push_back({1, 0, 16});
  sheet.triangles.push_back({2, 1, 17});
  EXPECT_EQ(close_border_notches(sheet.points, sheet.triangles, anything_may_be_added), 1u);
  const Facet<3>& closing = sheet.triangles.back();
  EXPECT_EQ(closing, (Facet<3>{17, 1, 16}));
  EXPECT_GT(facing_up(sheet.points, closing), 0);
  // The square corners of the sheet (90 degrees) stay as they are.
  Sheet plain = grid_sheet();
  EXPECT_EQ(close_border_notches(plain.points, plain.triangles, anything_may_be_added), 0u);
}

}  // namespace
}  // namespace sculpt
