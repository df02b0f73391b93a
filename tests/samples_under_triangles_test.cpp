// SPDX-License-Identifier: GPL-3.0-or-later
// Samples left off beneath a bordered surface, set into the triangle or edge over them
// (methods/robust/samples_under_triangles.hpp).
#include "methods/robust/samples_under_triangles.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "test_support.hpp"

namespace sculpt {
namespace {

// The unit grid over [0, 3] x [0, 3], two triangles a cell, facing up (+z).
std::vector<Facet<3>> grid_triangles(std::vector<Point<3>>& points) {
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 3; ++i) points.push_back({double(i), double(j), 0});
  }
  const auto at = [](int i, int j) { return 4 * j + i; };
  std::vector<Facet<3>> triangles;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return triangles;
}

// Every directed edge at most once: the triangles face one way and no edge has three.
bool consistently_oriented(const std::vector<Facet<3>>& triangles) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) {
      if (++directed[{t[j], t[(j + 1) % 3]}] > 1) return false;
    }
  }
  return true;
}

double facing_up(const std::vector<Point<3>>& p, const Facet<3>& f) {
  return (p[f[1]][0] - p[f[0]][0]) * (p[f[2]][1] - p[f[0]][1]) -
         (p[f[1]][1] - p[f[0]][1]) * (p[f[2]][0] - p[f[0]][0]);
}

TEST(Samples_under_triangles, ASampleJustBelowASheetIsSetIntoTheTriangleOverIt) {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles = grid_triangles(points);
  const auto border = testing::border_edges(triangles);
  points.push_back({1.7, 1.3, -0.05});  // under the triangle (1,1) (2,1) (2,2)
  const int sample = static_cast<int>(points.size()) - 1;

  EXPECT_EQ(set_in_left_off_samples(points, triangles), 1u);
  EXPECT_EQ(triangles.size(), 20u);  // 18, one of them split in three
  int at_sample = 0;
  for (const auto& t : triangles) {
    EXPECT_GT(facing_up(points, t), 0);
    at_sample += t[0] == sample || t[1] == sample || t[2] == sample;
  }
  EXPECT_EQ(at_sample, 3);
  EXPECT_TRUE(consistently_oriented(triangles));
  EXPECT_EQ(testing::border_edges(triangles), border) << "the border is kept";
}

TEST(Samples_under_triangles, ASampleUnderAFoldIsSetIntoItsEdge) {
  // Two triangles meeting at a valley along the x axis, facing up: a sample just below the
  // valley's edge projects into neither triangle (onto each plane beyond the edge).
  std::vector<Point<3>> points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0.5}, {0.5, -1, 0.5}};
  std::vector<Facet<3>> triangles = {{0, 1, 2}, {1, 0, 3}};
  points.push_back({0.5, 0, -0.1});
  const auto border = testing::border_edges(triangles);

  EXPECT_EQ(set_in_left_off_samples(points, triangles), 1u);
  EXPECT_EQ(triangles.size(), 4u);
  EXPECT_TRUE(consistently_oriented(triangles));
  EXPECT_EQ(testing::border_edges(triangles).size(), border.size());
  for (const auto& t : triangles) EXPECT_TRUE(t[0] == 4 || t[1] == 4 || t[2] == 4);
}

TEST(Samples_under_triangles, ASampleFarOffTheSheetOrBesideItStaysOff) {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles = grid_triangles(points);
  points.push_back({1.7, 1.3, -1.0});  // deeper than half the triangle's longest edge
  points.push_back({3.5, 1.5, 0.0});   // beside the sheet, over no triangle
  points.push_back({3.3, 3.2, 0.3});   // beyond the corner (3, 3), a border vertex, and over it
  const auto before = triangles;

  EXPECT_EQ(set_in_left_off_samples(points, triangles), 0u);
  EXPECT_EQ(triangles, before);
}

// Beyond a corner no triangle or edge lies under a sample: over the apex v of a pyramid (its four
// faces facing out), s takes v's place in v's four triangles and v is set into the one it lies
// nearest, which it now lies beneath.
TEST(Samples_under_triangles, ASampleOverACornerTakesItsPlace) {
  std::vector<Point<3>> points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
  const int v = 4, s = 5;
  points.push_back({0.02, 0.01, 1.3});
  std::vector<Facet<3>> triangles = {{0, 1, v}, {1, 2, v}, {2, 3, v}, {3, 0, v}};
  const auto border = testing::border_edges(triangles);

  EXPECT_EQ(set_in_left_off_samples(points, triangles), 1u);
  EXPECT_EQ(triangles.size(), 6u);
  EXPECT_TRUE(consistently_oriented(triangles));
  EXPECT_EQ(testing::border_edges(triangles), border) << "the border is kept";
  // s has every corner of the base beside it; v is on the three parts of the triangle it was
  // set into, two of them through s.
  std::set<int> beside_s;
  int through_v = 0, through_v_and_s = 0;
  for (const auto& t : triangles) {
    const bool has_s = t[0] == s || t[1] == s || t[2] == s;
    const bool has_v = t[0] == v || t[1] == v || t[2] == v;
    if (has_s) beside_s.insert(t.begin(), t.end());
    through_v += has_v;
    through_v_and_s += has_v && has_s;
  }
  EXPECT_EQ(beside_s, (std::set<int>{0, 1, 2, 3, v, s}));
  EXPECT_EQ(through_v, 3);
  EXPECT_EQ(through_v_and_s, 2);
  // Too far over the corner (more than half the longest edge at v): left off.
  points[s][2] = 3.0;
  std::vector<Facet<3>> far = {{0, 1, v}, {1, 2, v}, {2, 3, v}, {3, 0, v}};
  EXPECT_EQ(set_in_left_off_samples(points, far), 0u);
}

}  // namespace
}  // namespace sculpt
