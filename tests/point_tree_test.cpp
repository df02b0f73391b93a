// SPDX-License-Identifier: GPL-3.0-or-later
// The k-d tree's answers against brute force: the k-th nearest distances and neighbours that
// measure the samples' spacing (spanning_openings.hpp) and the "any point within" query of the
// circumball tests (circumball_query.hpp).
#include "core/point_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace sculpt {
namespace {

template <int D>
double brute_kth_nearest2(const std::vector<Point<D>>& points, std::size_t i, int k) {
  std::vector<double> d2;
  for (const auto& p : points) {
    double sum = 0;
    for (int c = 0; c < D; ++c) sum += (p[c] - points[i][c]) * (p[c] - points[i][c]);
    d2.push_back(sum);
  }
  if (static_cast<int>(d2.size()) < k) return INFINITY;
  std::nth_element(d2.begin(), d2.begin() + (k - 1), d2.end());
  return d2[k - 1];
}

// Uniform points, a dense clump and a lattice (many equal distances, points on split planes).
template <int D>
std::vector<Point<D>> awkward_points(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Point<D>> points;
  for (int i = 0; i < 400; ++i) {
    Point<D> p;
    for (int c = 0; c < D; ++c) p[c] = unit(random);
    points.push_back(p);
  }
  for (int i = 0; i < 200; ++i) {
    Point<D> p;
    for (int c = 0; c < D; ++c) p[c] = 0.5 + 1e-3 * unit(random);
    points.push_back(p);
  }
  for (int i = 0; i < 125; ++i) {
    Point<D> p;
    for (int c = 0, stride = 1; c < D; ++c, stride *= 5) p[c] = 2 + 0.1 * ((i / stride) % 5);
    points.push_back(p);
  }
  return points;
}

template <int D>
void expect_kth_nearest_match_brute_force() {
  const auto points = awkward_points<D>(7);
  const Point_tree<D> tree(points.data(), points.data() + points.size());
  for (int k : {1, 2, 7, Point_tree<D>::most_neighbours}) {
    const std::vector<double> found = tree.kth_nearest_distances2(k);
    ASSERT_EQ(found.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(found[i], brute_kth_nearest2<D>(points, i, k)) << "k " << k << ", point " << i;
    }
  }
}

TEST(PointTree, KthNearestDistancesAreThoseOfBruteForce3) {
  expect_kth_nearest_match_brute_force<3>();
}

TEST(PointTree, KthNearestDistancesAreThoseOfBruteForce2) {
  expect_kth_nearest_match_brute_force<2>();
}

// k_nearest lists the points whose distances are the k smallest, nearest first (ties in any
// order: compared by distance).
template <int D>
void expect_k_nearest_match_brute_force() {
  const auto points = awkward_points<D>(5);
  const Point_tree<D> tree(points.data(), points.data() + points.size());
  for (int k : {1, 7, Point_tree<D>::most_neighbours}) {
    const std::vector<int> found = tree.k_nearest(k);
    ASSERT_EQ(found.size(), points.size() * k);
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (int j = 0; j < k; ++j) {
        const int neighbour = found[i * k + j];
        ASSERT_GE(neighbour, 0);
        double d2 = 0;
        for (int c = 0; c < D; ++c)
          d2 += (points[neighbour][c] - points[i][c]) * (points[neighbour][c] - points[i][c]);
        ASSERT_EQ(d2, brute_kth_nearest2<D>(points, i, j + 1))
            << "k " << k << ", point " << i << ", rank " << j;
      }
    }
  }
}

TEST(PointTree, KNearestAreThoseOfBruteForce3) {
  expect_k_nearest_match_brute_force<3>();
}

TEST(PointTree, KNearestAreThoseOfBruteForce2) {
  expect_k_nearest_match_brute_force<2>();
}

TEST(PointTree, FewerPointsThanKLeaveTheRestUnfilled) {
  const std::vector<Point<3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  const Point_tree<3> tree(points.data(), points.data() + points.size());
  const std::vector<int> found = tree.k_nearest(4);
  ASSERT_EQ(found.size(), 12u);
  EXPECT_EQ(std::vector<int>(found.begin(), found.begin() + 4), (std::vector<int>{0, 1, 2, -1}));
  EXPECT_EQ(std::vector<int>(found.begin() + 8, found.end()), (std::vector<int>{2, 0, 1, -1}));
  EXPECT_EQ(tree.k_nearest_to({0.9, 0, 0}, 4), (std::vector<int>{1, 0, 2}));
}

TEST(PointTree, FewerPointsThanKGiveInfinity) {
  const std::vector<Point<3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  const Point_tree<3> tree(points.data(), points.data() + points.size());
  const std::vector<double> third = tree.kth_nearest_distances2(3);
  EXPECT_EQ(third[0], 4.0);
  EXPECT_EQ(third[1], 5.0);
  EXPECT_EQ(third[2], 5.0);
  for (double d2 : tree.kth_nearest_distances2(4)) EXPECT_TRUE(std::isinf(d2));
}

TEST(PointTree, AnyWithinIsStrictAndSeesEveryPoint) {
  const auto points = awkward_points<3>(11);
  const Point_tree<3> tree(points.data(), points.data() + points.size());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.5, 2.5);
  for (int q = 0; q < 300; ++q) {
    const Point<3> x{unit(random), unit(random), unit(random)};
    double nearest2 = INFINITY;
    for (const auto& p : points) {
      double d2 = 0;
      for (int c = 0; c < 3; ++c) d2 += (p[c] - x[c]) * (p[c] - x[c]);
      nearest2 = std::min(nearest2, d2);
    }
    EXPECT_FALSE(tree.any_within(x, nearest2)) << q;  // strictly closer only
    EXPECT_TRUE(tree.any_within(x, std::nextafter(nearest2, INFINITY))) << q;
  }
}

}  // namespace
}  // namespace sculpt
