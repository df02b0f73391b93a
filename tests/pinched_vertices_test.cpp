// SPDX-License-Identifier: GPL-3.0-or-later
// Fans of triangles pinched at a vertex, joined (methods/robust/pinched_vertices.hpp).
#include "methods/robust/pinched_vertices.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "test_support.hpp"

namespace sculpt {
namespace {

constexpr double pi = 3.14159265358979323846;

// Samples around the origin (sample 0) on the plane z = 0, at angles of 30 degrees.
std::vector<Point<3>> wheel() {
  std::vector<Point<3>> points = {{0, 0, 0}};
  for (int i = 0; i < 12; ++i) {
    points.push_back({std::cos(i * pi / 6), std::sin(i * pi / 6), 0});
  }
  return points;
}

// The triangle (0, i, i + 1) of the wheel, facing up.
Facet<3> spoke(int i) {
  return {0, 1 + i % 12, 1 + (i + 1) % 12};
}

bool manifold_at(const std::vector<Facet<3>>& triangles, int vertex) {
  // The link of the vertex (the edges opposite it) is one path or cycle.
  std::map<int, int> next;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) {
      if (t[j] == vertex && !next.emplace(t[(j + 1) % 3], t[(j + 2) % 3]).second) return false;
    }
  }
  std::map<int, int> arriving;
  for (const auto& [from, to] : next) ++arriving[to];
  int starts = 0;
  for (const auto& [from, to] : next) starts += arriving.count(from) == 0;
  if (starts > 1) return false;
  int from = next.begin()->first;
  for (const auto& [v, to] : next) {
    if (!arriving.count(v)) from = v;
  }
  std::size_t visited = 0;
  for (int v = from; next.count(v) && visited <= next.size(); v = next[v]) ++visited;
  return visited == next.size();
}

const auto anything_may_be_added = [](const Facet<3>&) { return false; };

// A sheet of (side - 1) x (side - 1) cells, two triangles a cell; vertex (i, j) is side * j + i.
std::vector<Facet<3>> grid_sheet(int side) {
  std::vector<Facet<3>> sheet;
  const auto at = [&](int i, int j) { return side * j + i; };
  for (int j = 0; j + 1 < side; ++j) {
    for (int i = 0; i + 1 < side; ++i) {
      sheet.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      sheet.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return sheet;
}

TEST(Pinched_vertices, TwoFansMeetingAtAVertexAreJoinedAcrossTheNarrowerGap) {
  // Fans of two and three spokes, with gaps of one spoke (30 degrees) and six (180 degrees).
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1), spoke(3), spoke(4), spoke(5)};
  ASSERT_FALSE(manifold_at(triangles, 0));
  EXPECT_EQ(join_pinched_vertices(wheel(), triangles, anything_may_be_added), 1u);
  ASSERT_EQ(triangles.size(), 6u);
  Facet<3> added = triangles.back();
  while (added[0] != 0) std::rotate(added.begin(), added.begin() + 1, added.end());
  EXPECT_EQ(added, spoke(2)) << "the 30-degree gap is the one closed, facing up";
  EXPECT_TRUE(manifold_at(triangles, 0));
}

TEST(Pinched_vertices, AFanAsThinAsASliverIsJoinedToo) {
  // A fan from 0 to 120 degrees and one triangle 4 degrees wide at 130: the 10-degree gap
  // between them is closed (the sliver's far edge, just beyond the gap, is not inside it).
  std::vector<Point<3>> points = {{0, 0, 0}};
  for (double degrees : {0.0, 60.0, 120.0, 130.0, 134.0}) {
    points.push_back({std::cos(degrees * pi / 180), std::sin(degrees * pi / 180), 0});
  }
  std::vector<Facet<3>> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}};
  EXPECT_EQ(join_pinched_vertices(points, triangles, anything_may_be_added), 1u);
  ASSERT_EQ(triangles.size(), 4u);
  Facet<3> added = triangles.back();
  while (added[0] != 0) std::rotate(added.begin(), added.begin() + 1, added.end());
  EXPECT_EQ(added, (Facet<3>{0, 3, 4}));
  EXPECT_TRUE(manifold_at(triangles, 0));
}

TEST(Pinched_vertices, NoJoinWhereNoTriangleMayBeAdded) {
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1), spoke(3), spoke(4), spoke(5)};
  const auto before = triangles;
  EXPECT_EQ(join_pinched_vertices(wheel(), triangles, [](const Facet<3>&) { return true; }), 0u);
  EXPECT_EQ(triangles, before);
}

TEST(Pinched_vertices, AFanIsNotClosedOnItself) {
  // A fan of eleven spokes (a 30-degree notch) and a second fan standing up from the centre,
  // which no triangle may reach: the narrowest pair at the centre is the notch's, which would
  // close the first fan on itself and leave the pinch; nothing is added.
  std::vector<Point<3>> points = wheel();
  const int up = static_cast<int>(points.size());
  points.push_back({0.3, 0.3, 2});
  points.push_back({-0.3, 0.3, 2});
  std::vector<Facet<3>> triangles;
  for (int i = 0; i < 11; ++i) triangles.push_back(spoke(i));
  triangles.push_back({0, up, up + 1});
  const auto reaches_up = [&](const Facet<3>& f) { return f[0] >= up || f[1] >= up || f[2] >= up; };
  ASSERT_FALSE(manifold_at(triangles, 0));
  EXPECT_EQ(join_pinched_vertices(points, triangles, reaches_up), 0u);
}

TEST(Pinched_vertices, NoJoinReachesOverAThirdFan) {
  // Fans at 0-60, 120-150 and 180-210 degrees; the gaps next to the middle fan may not be
  // closed, so a triangle from 60 to 180 degrees would lie over it.
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1), spoke(4), spoke(6)};
  const auto next_to_middle = [](const Facet<3>& f) {
    for (int v : f) {
      if (v == 1 + 4 || v == 1 + 5) return true;
    }
    return false;
  };
  const auto before = triangles;
  join_pinched_vertices(wheel(), triangles, next_to_middle);
  for (std::size_t t = before.size(); t < triangles.size(); ++t) {
    Facet<3> added = triangles[t];
    while (added[0] != 0) std::rotate(added.begin(), added.begin() + 1, added.end());
    EXPECT_NE(added, (Facet<3>{0, 1 + 2, 1 + 6})) << "over the fan at 120-150 degrees";
  }
}

TEST(Pinched_vertices, AFanStillPinchedIsDroppedWhenNoSampleIsLost) {
  // A sheet of 8 x 8 cells and a flap from its middle vertex to an edge of its border: at the
  // middle vertex the flap is a fan of its own, and all its samples are on the sheet too.
  const int side = 9;
  const auto at = [&](int i, int j) { return side * j + i; };
  const std::vector<Facet<3>> sheet = grid_sheet(side);
  std::vector<Facet<3>> triangles = sheet;
  triangles.push_back({at(4, 4), at(1, 0), at(0, 0)});  // on the border edge (0,0) -> (1,0)
  ASSERT_FALSE(manifold_at(triangles, at(4, 4)));
  EXPECT_EQ(drop_pinched_fans(triangles, side * side), 1u);
  EXPECT_EQ(triangles, sheet);
}

TEST(Pinched_vertices, TheFanKeptIsTheOneOnTheLargerPiece) {
  // A sheet of 8 x 8 cells with a flap of three triangles hung from its corner: the flap has more
  // triangles at the corner than the sheet's two, but the sheet is the larger piece. Its corner
  // stays; the flap, whose samples are on it alone, stays too.
  const int side = 9;
  const auto at = [&](int i, int j) { return side * j + i; };
  std::vector<Facet<3>> triangles = grid_sheet(side);
  const int flap = side * side;
  for (int k = 0; k < 3; ++k) triangles.push_back({at(0, 0), flap + k, flap + k + 1});
  ASSERT_FALSE(manifold_at(triangles, at(0, 0)));
  const auto before = triangles;
  EXPECT_EQ(drop_pinched_fans(triangles, flap + 4), 0u);
  EXPECT_EQ(triangles, before);
}

TEST(Pinched_vertices, AFanWhoseDropWouldCutOffASmallPieceStays) {
  // Two fans at the centre that nothing joins: five spokes, and one spoke whose samples are
  // also on a strip of four triangles beyond the rim, reached through it only.
  std::vector<Point<3>> points = wheel();
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1), spoke(2), spoke(3), spoke(4), spoke(7)};
  // Beyond the rim at 210 and 240 degrees, a strip of triangles holding samples 8 and 9.
  const int outer = static_cast<int>(points.size());
  for (int i = 0; i < 4; ++i) {
    const double angle = (200 + 15 * i) * pi / 180;
    points.push_back({2 * std::cos(angle), 2 * std::sin(angle), 0});
  }
  triangles.push_back({1 + 7, outer + 1, outer + 2});
  triangles.push_back({1 + 7, outer + 2, 1 + 8});
  triangles.push_back({1 + 8, outer + 2, outer + 3});
  triangles.push_back({1 + 7, outer, outer + 1});
  ASSERT_FALSE(manifold_at(triangles, 0));
  auto kept = triangles;
  EXPECT_EQ(drop_pinched_fans(kept, points.size()), 0u);
  EXPECT_EQ(kept, triangles);
}

TEST(Pinched_vertices, FansFoldedAgainstEachOtherAreLeftAlone) {
  // The second fan turned over (facing down): a triangle joining them would face against one.
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1)};
  const std::vector<Point<3>> points = wheel();
  triangles.push_back({0, 1 + 5, 1 + 4});  // facing down
  triangles.push_back({0, 1 + 6, 1 + 5});
  const auto before = triangles;
  EXPECT_EQ(join_pinched_vertices(points, triangles, anything_may_be_added), 0u);
  EXPECT_EQ(triangles, before);
}

}  // namespace
}  // namespace sculpt
