// SPDX-License-Identifier: GPL-3.0-or-later
// Gaps in the sampling filled after the bordered rule (methods/robust/gap_filling.hpp): the loops
// found, the fills made, and the fills refused.
#include "methods/robust/gap_filling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <unordered_set>

#include "test_support.hpp"

namespace sculpt {
namespace {

// An octahedron, its faces oriented outwards.
std::vector<Point<3>> octahedron_points() {
  return {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
}

std::vector<Facet<3>> octahedron_faces() {
  return {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
}

// Every directed edge once and its reverse once: a closed, consistently oriented surface.
void expect_closed_and_oriented(const std::vector<Facet<3>>& triangles) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) ++directed[{t[j], t[(j + 1) % 3]}];
  }
  for (const auto& [edge, times] : directed) {
    EXPECT_EQ(times, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
}

const auto never_over_an_opening = [](const Facet<3>&) { return false; };

// The edge tables the mending reads (key_table.hpp) answer as std::unordered_map would, through
// many growths, for keys of edges both ways round.
TEST(Gap_filling, TheEdgeTableAnswersAsAMapWould) {
  Key_table<int> table;
  std::map<std::uint64_t, int> expected;
  std::mt19937 random(3);
  std::uniform_int_distribution<int> vertex(0, 3000);
  for (int k = 0; k < 20000; ++k) {
    const int a = vertex(random), b = vertex(random);
    const std::uint64_t key = k % 2 ? directed_key(a, b) : edge_key(a, b);
    ++table[key];
    ++expected[key];
  }
  EXPECT_EQ(table.size(), expected.size());
  for (const auto& [key, count] : expected) {
    ASSERT_NE(table.find(key), nullptr);
    EXPECT_EQ(table.at(key), count);
    EXPECT_EQ(table.count(key), 1u);
  }
  const std::uint64_t absent = directed_key(5000, 5001);
  EXPECT_EQ(table.find(absent), nullptr);
  EXPECT_EQ(table.count(absent), 0u);
  EXPECT_THROW(table.at(absent), std::out_of_range);
  const Key_table<int> listed = {{directed_key(1, 2), 7}, {directed_key(2, 1), 9}};
  EXPECT_EQ(listed.at(directed_key(1, 2)), 7);
  EXPECT_EQ(listed.at(directed_key(2, 1)), 9);
  EXPECT_EQ(listed.size(), 2u);
}

TEST(Gap_filling, ALoopIsFollowedInTheTrianglesDirection) {
  auto faces = octahedron_faces();
  faces.erase(faces.begin());  // (0, 2, 4) goes: the loop 0 -> 4 -> 2 in the others' direction
  const auto loops = simple_border_loops(faces);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].vertices.size(), 3u);
  std::vector<int> loop = loops[0].vertices, apexes = loops[0].apexes;
  const auto at = std::find(loop.begin(), loop.end(), 0) - loop.begin();
  std::rotate(loop.begin(), loop.begin() + at, loop.end());
  std::rotate(apexes.begin(), apexes.begin() + at, apexes.end());
  EXPECT_EQ(loop, (std::vector<int>{0, 4, 2}));
  // The triangles on 0 -> 4, 4 -> 2 and 2 -> 0: (3, 0, 4), (2, 1, 4) and (2, 0, 5).
  EXPECT_EQ(apexes, (std::vector<int>{3, 1, 5}));
}

// Two holes side by side sharing a vertex: the square 0..3 on z = 0 with a fan of triangles
// around vertex 4 at its centre, two of whose triangles are missing, (4, 1, 2) and (4, 3, 0).
// At 4 two fans meet (its triangles (4, 0, 1) and (4, 2, 3)), each hole between an edge arriving
// from one fan and one leaving the other: two loops of three, each filled.
TEST(Gap_filling, HolesSharingAVertexAreTwoLoops) {
  const std::vector<Point<3>> points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 0},
                                        {0, -3, 0},  {3, 0, 0},  {0, 3, 0}, {-3, 0, 0}};
  // The fan's two triangles, and around the square a ring so that the square's sides are inner
  // edges.
  std::vector<Facet<3>> surface = {{4, 0, 1}, {4, 2, 3}, {0, 5, 1}, {1, 5, 6}, {1, 6, 2},
                                   {2, 6, 7}, {2, 7, 3}, {3, 7, 8}, {3, 8, 0}, {0, 8, 5}};
  const auto loops = simple_border_loops(surface);
  ASSERT_EQ(loops.size(), 3u);  // the two holes and the ring's outer border
  std::set<std::vector<int>> small;
  for (const auto& loop : loops) {
    if (loop.vertices.size() != 3) continue;
    std::vector<int> sorted = loop.vertices;
    std::sort(sorted.begin(), sorted.end());
    small.insert(sorted);
  }
  EXPECT_EQ(small, (std::set<std::vector<int>>{{1, 2, 4}, {0, 3, 4}}));
  // Left out when asked: the fans at a pinch may be dropped first.
  EXPECT_EQ(simple_border_loops(surface, Pinches::left_out).size(), 1u);
  EXPECT_EQ(fill_gaps(points, surface, never_over_an_opening).filled, 2u);
  EXPECT_EQ(surface.size(), 12u);
  EXPECT_EQ(simple_border_loops(surface).size(), 1u);
  // The fills face as the rest: every directed edge once.
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : surface) {
    for (int j = 0; j < 3; ++j) EXPECT_EQ(++directed[std::make_pair(t[j], t[(j + 1) % 3])], 1);
  }
}

// A piece of the border (edges joined at shared vertices) counts as torn when every edge of it
// is on a torn loop: a torn loop sharing a vertex with another loop that is not torn leaves its
// piece an opening.
TEST(Gap_filling, ABorderPieceIsTornWhenAllItsLoopsAre) {
  // Two triangles meeting at vertex 4 only (a bow tie): one border piece of six edges.
  const std::vector<Facet<3>> bowtie = {{4, 0, 1}, {4, 2, 3}};
  const std::unordered_set<std::uint64_t> both = {edge_key(4, 0), edge_key(0, 1), edge_key(1, 4),
                                                  edge_key(4, 2), edge_key(2, 3), edge_key(3, 4)};
  EXPECT_EQ(count_pieces_not_openings(bowtie, edge_uses(bowtie), both).torn, 1u);
  const std::unordered_set<std::uint64_t> one = {edge_key(4, 0), edge_key(0, 1), edge_key(1, 4)};
  EXPECT_EQ(count_pieces_not_openings(bowtie, edge_uses(bowtie), one).torn, 0u);
  // Two triangles apart: two pieces, one torn.
  const std::vector<Facet<3>> apart = {{0, 1, 2}, {5, 6, 7}};
  EXPECT_EQ(count_pieces_not_openings(apart, edge_uses(apart),
                                      {edge_key(0, 1), edge_key(1, 2), edge_key(2, 0)})
                .torn,
            1u);
  EXPECT_EQ(count_pieces_not_openings(apart, edge_uses(apart), {}).torn, 0u);
}

// A piece of the border that is not torn is short when it passes through fewer samples than the
// rim of the smallest opening the kind choice can find (19): a hole cut in the sheet. Small loops
// pinched together at a sample are one piece, counted by its samples.
TEST(Gap_filling, ABorderPieceThroughFewerSamplesThanAnOpeningsRimIsShort) {
  // A fan of triangles around sample 0 whose rim passes through `rim` samples: one border loop.
  const auto fan = [](int rim, int first) {
    std::vector<Facet<3>> triangles;
    for (int i = 0; i < rim; ++i) {
      triangles.push_back({first, first + 1 + i, first + 1 + (i + 1) % rim});
    }
    return triangles;
  };
  const auto pieces = [](const std::vector<Facet<3>>& surface,
                         const std::unordered_set<std::uint64_t>& torn) {
    return count_pieces_not_openings(surface, edge_uses(surface), torn);
  };
  EXPECT_EQ(smallest_opening_rim, 19u);
  EXPECT_EQ(pieces(fan(18, 0), {}).too_short, 1u);
  EXPECT_EQ(pieces(fan(19, 0), {}).too_short, 0u);
  // A torn piece is torn, not short.
  const std::vector<Facet<3>> small = fan(5, 0);
  std::unordered_set<std::uint64_t> rim;
  for (int i = 0; i < 5; ++i) rim.insert(edge_key(1 + i, 1 + (i + 1) % 5));
  const auto torn = pieces(small, rim);
  EXPECT_EQ(torn.torn, 1u);
  EXPECT_EQ(torn.too_short, 0u);
  // Fans of 9 and 10 rim samples pinched at one rim sample: one piece of 19 edges through 18
  // samples, short (counted by its edges, it would not be); of 9 and 11, 19 samples.
  const auto pinched = [&](int second_rim) {
    std::vector<Facet<3>> triangles = fan(9, 0);
    for (Facet<3> t : fan(second_rim, 100)) {
      for (int& v : t) v = v == 101 ? 1 : v;  // the second fan's first rim sample is the first's
      triangles.push_back(t);
    }
    return triangles;
  };
  EXPECT_EQ(edge_uses(pinched(10)).size() - 9 - 10, 19u);  // the spokes, then the rim's edges
  EXPECT_EQ(pieces(pinched(10), {}).too_short, 1u);
  EXPECT_EQ(pieces(pinched(11), {}).too_short, 0u);
}

TEST(Gap_filling, TwoLoopsThroughOneVertexAreNotSimple) {
  // Two triangles meeting at vertex 0 only (a bowtie): its border passes 0 twice.
  const std::vector<Facet<3>> bowtie = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_TRUE(simple_border_loops(bowtie).empty());
  EXPECT_EQ(simple_border_loops({{0, 1, 2}}).size(), 1u);
  // Two triangles facing opposite ways on the edge 1-2: two border edges arrive at 1 (from 0
  // and 3) and two leave 2 (to 0 and 3).
  EXPECT_TRUE(simple_border_loops({{0, 1, 2}, {1, 2, 3}}).empty());
}

TEST(Gap_filling, AMissingTriangleOrTwoAreFilledFacingTheRest) {
  const auto points = octahedron_points();
  for (int missing : {1, 2}) {
    SCOPED_TRACE(missing);
    auto faces = octahedron_faces();
    // One face, or two faces sharing the edge 2-4 (a loop of 4: 0, 4, 1, 2 in some order).
    faces.erase(faces.begin(), faces.begin() + missing);
    auto surface = faces;
    EXPECT_EQ(fill_gaps(points, surface, never_over_an_opening).filled, 1u);
    EXPECT_EQ(surface.size(), 8u);
    expect_closed_and_oriented(surface);
  }
}

TEST(Gap_filling, AFillOverAnOpeningOrOnAnEdgeAlreadyThereIsRefused) {
  const auto points = octahedron_points();
  auto faces = octahedron_faces();
  faces.erase(faces.begin());
  auto surface = faces;
  EXPECT_EQ(fill_gaps(points, surface, [](const Facet<3>&) { return true; }).filled, 0u);
  EXPECT_EQ(surface, faces);

  // The loop 0 -> 4 -> 1 -> 2 left by removing (0, 2, 4) and (2, 1, 4). Its diagonals 0-1 and 2-4
  // are made edges elsewhere, each by a closed tetrahedron on two new apexes (no border added):
  // with one of them taken, the fill uses the other; with both, it is refused.
  const auto tetrahedron = [](int a, int b, int c, int d) {
    return std::vector<Facet<3>>{{a, b, c}, {a, c, d}, {a, d, b}, {b, d, c}};
  };
  std::vector<Point<3>> with_apexes = points;
  for (double z : {3.0, 4.0, 5.0, 6.0}) with_apexes.push_back({0.1 * z, 0.2, z});
  std::vector<Facet<3>> holed(faces.begin() + 1, faces.end());
  for (const auto& t : tetrahedron(0, 1, 6, 7)) holed.push_back(t);
  auto one_taken = holed;
  EXPECT_EQ(fill_gaps(with_apexes, one_taken, never_over_an_opening).filled, 1u);
  expect_closed_and_oriented(one_taken);
  for (const auto& t : tetrahedron(2, 4, 8, 9)) holed.push_back(t);
  auto both_taken = holed;
  EXPECT_EQ(fill_gaps(with_apexes, both_taken, never_over_an_opening).filled, 0u);
  EXPECT_EQ(both_taken, holed);
}

// Every triangulation of the polygon 0..k-1, as triangles (v_j, v_m, v_i) on each sub-chain.
std::vector<std::vector<Facet<3>>> every_triangulation(int i, int j) {
  if (j == i + 1) return {{}};
  std::vector<std::vector<Facet<3>>> all;
  for (int m = i + 1; m < j; ++m) {
    for (const auto& left : every_triangulation(i, m)) {
      for (const auto& right : every_triangulation(m, j)) {
        std::vector<Facet<3>> triangles = left;
        triangles.insert(triangles.end(), right.begin(), right.end());
        triangles.push_back({j, m, i});
        all.push_back(triangles);
      }
    }
  }
  return all;
}

// The cosine at a fill's sharpest fold, the fill given by loop positions: between two of its
// triangles on a shared edge, and between one on a loop edge and the surface's triangle there.
double sharpest_fold(const std::vector<Point<3>>& points, const std::vector<Facet<3>>& fill,
                     const std::vector<std::array<double, 3>>& edge_normals) {
  const auto unit_normal = [&](const Facet<3>& t) {
    std::array<double, 3> u, v;
    for (int c = 0; c < 3; ++c) {
      u[c] = points[t[1]][c] - points[t[0]][c];
      v[c] = points[t[2]][c] - points[t[0]][c];
    }
    std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                               u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= length;
    return n;
  };
  const auto cosine = [](std::array<double, 3> a, std::array<double, 3> b) {
    return (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
           std::sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) *
                     (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  };
  const int k = static_cast<int>(edge_normals.size());
  std::map<std::pair<int, int>, std::vector<std::array<double, 3>>> on_edge;
  for (const auto& t : fill) {
    for (int j = 0; j < 3; ++j) {
      const int a = std::min(t[j], t[(j + 1) % 3]), b = std::max(t[j], t[(j + 1) % 3]);
      on_edge[{a, b}].push_back(unit_normal(t));
    }
  }
  double sharpest = 1;
  for (auto& [edge, normals] : on_edge) {
    const auto [a, b] = edge;
    if (b == a + 1) normals.push_back(edge_normals[a]);
    if (a == 0 && b == k - 1) normals.push_back(edge_normals[k - 1]);
    EXPECT_EQ(normals.size(), 2u);
    if (normals.size() == 2) sharpest = std::min(sharpest, cosine(normals[0], normals[1]));
  }
  return sharpest;
}

// The fill is the least folded of all triangulations of the loop: on random crooked loops of 4
// to 7 samples, one diagonal of which the surface has already, its sharpest fold equals the best
// of every triangulation's without that diagonal, and is its own.
TEST(Gap_filling, TheFillIsTheLeastFoldedTriangulation) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  for (int k = 4; k <= 7; ++k) {
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE(::testing::Message() << k << " samples, trial " << trial);
      // Round a circle clockwise seen from above, as the border of a hole in a sheet facing up.
      // The loop's samples are numbered 10 + 3 i, its positions i; the diagonal between
      // positions 1 and 3 is an edge of the surface already.
      std::vector<Point<3>> points(10 + 3 * k);
      std::vector<Point<3>> at_position;
      std::vector<int> loop;
      std::vector<std::array<double, 3>> edge_normals;
      for (int i = 0; i < k; ++i) {
        const double angle = -2 * M_PI * i / k, radius = 1 + 0.3 * jitter(random);
        at_position.push_back({radius * std::cos(angle), radius * std::sin(angle), jitter(random)});
        loop.push_back(10 + 3 * i);
        points[loop.back()] = at_position.back();
        edge_normals.push_back({jitter(random), jitter(random), 1.0});
      }
      const Edge_uses edges = {{edge_key(loop[1], loop[3]), 2}};
      const Loop_fill fill = least_folded_fill(points, loop, edge_normals, edges);
      ASSERT_EQ(fill.triangles.size(), static_cast<std::size_t>(k - 2));
      const auto uses_diagonal = [](const std::vector<Facet<3>>& triangles, int a, int b) {
        for (const auto& t : triangles) {
          if (std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) return true;
        }
        return false;
      };
      double best = -2;
      for (const auto& triangulation : every_triangulation(0, k - 1)) {
        if (uses_diagonal(triangulation, 1, 3)) continue;
        best = std::max(best, sharpest_fold(at_position, triangulation, edge_normals));
      }
      EXPECT_NEAR(fill.sharpest_fold_cos, best, 1e-9);
      // The fill in loop positions.
      std::vector<Facet<3>> in_positions;
      for (const auto& t : fill.triangles) {
        Facet<3> positions;
        for (int j = 0; j < 3; ++j) positions[j] = (t[j] - 10) / 3;
        in_positions.push_back(positions);
      }
      EXPECT_FALSE(uses_diagonal(in_positions, 1, 3));
      EXPECT_NEAR(sharpest_fold(at_position, in_positions, edge_normals), fill.sharpest_fold_cos,
                  1e-9);
      // Beside a degenerate triangle of the surface there is no fold to measure: no fill.
      std::vector<std::array<double, 3>> one_degenerate = edge_normals;
      one_degenerate[trial % k] = {0, 0, 0};
      EXPECT_TRUE(least_folded_fill(points, loop, one_degenerate, edges).triangles.empty());
    }
  }
}

// A flat strip around a round hole: `rim` samples at radius 1 and as many at radius 1.5, as
// triangles facing up. Its inner loop is the hole; its outer loop is the strip's own border.
struct Ring {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles;
};

Ring ring_around_a_hole(int rim) {
  Ring ring;
  for (double radius : {1.0, 1.5}) {
    for (int i = 0; i < rim; ++i) {
      const double angle = 2 * M_PI * i / rim;
      ring.points.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
  }
  for (int i = 0; i < rim; ++i) {
    const int inner = i, next_inner = (i + 1) % rim, outer = rim + i, next_outer = rim + next_inner;
    ring.triangles.push_back({inner, outer, next_outer});
    ring.triangles.push_back({inner, next_outer, next_inner});
  }
  return ring;
}

TEST(Gap_filling, TheHoleIsFilledNotTheOuterBorder) {
  const Ring ring = ring_around_a_hole(12);
  EXPECT_EQ(simple_border_loops(ring.triangles).size(), 2u);
  auto surface = ring.triangles;
  EXPECT_EQ(fill_gaps(ring.points, surface, never_over_an_opening).filled, 1u);
  // 10 triangles fill the hole of 12, all facing up as the ring does; the outer border stays.
  ASSERT_EQ(surface.size(), ring.triangles.size() + 10);
  for (std::size_t t = ring.triangles.size(); t < surface.size(); ++t) {
    for (int v : surface[t]) EXPECT_LT(v, 12);
    const auto& p = ring.points;
    const auto& f = surface[t];
    const double up = (p[f[1]][0] - p[f[0]][0]) * (p[f[2]][1] - p[f[0]][1]) -
                      (p[f[1]][1] - p[f[0]][1]) * (p[f[2]][0] - p[f[0]][0]);
    EXPECT_GT(up, 0);
  }
  // The outer border of a sheet alone is never filled: each ear lies back over the sheet.
  std::vector<Point<3>> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  std::vector<Facet<3>> fan = {{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {4, 3, 0}};
  EXPECT_EQ(fill_gaps(square, fan, never_over_an_opening).filled, 0u);
  EXPECT_EQ(fan.size(), 4u);
}

TEST(Gap_filling, LoopsLongerThanTheLimitAreLeft) {
  Ring ring = ring_around_a_hole(longest_gap_filled + 1);
  EXPECT_EQ(fill_gaps(ring.points, ring.triangles, never_over_an_opening).filled, 0u);
  ring = ring_around_a_hole(longest_gap_filled);
  EXPECT_EQ(fill_gaps(ring.points, ring.triangles, never_over_an_opening).filled, 1u);
}

}  // namespace
}  // namespace sculpt
