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

TEST(Pinched_vertices, NoJoinWhereNoTriangleMayBeAdded) {
  std::vector<Facet<3>> triangles = {spoke(0), spoke(1), spoke(3), spoke(4), spoke(5)};
  const auto before = triangles;
  EXPECT_EQ(join_pinched_vertices(wheel(), triangles, [](const Facet<3>&) { return true; }), 0u);
  EXPECT_EQ(triangles, before);
}

TEST(Pinched_vertices, AFanIsNotClosedOnItself) {
  // One fan of eleven spokes with a single gap: a notch, no pinch; nothing to join.
  std::vector<Facet<3>> triangles;
  for (int i = 0; i < 11; ++i) triangles.push_back(spoke(i));
  EXPECT_EQ(join_pinched_vertices(wheel(), triangles, anything_may_be_added), 0u);
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
