// SPDX-License-Identifier: GPL-3.0-or-later
// Input the algorithm cannot work on is refused with an Input_error naming the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sculpt/sculpt.hpp>

namespace sculpt {
namespace {

template <int D>
std::string refusal(const std::vector<Point<D>>& points, const Options& options = {}) {
  try {
    reconstruct(points, options);
  } catch (const Input_error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Bad_input, TooFewPoints) {
  EXPECT_NE(refusal<2>({{0, 0}, {1, 0}}).find("at least 3"), std::string::npos);
  EXPECT_NE(refusal<3>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("at least 4"), std::string::npos);
  EXPECT_NE(refusal<3>({}).find("got 0"), std::string::npos);
}

TEST(Bad_input, NotFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Points are named by their place counted from 1, as a reader of the file counts.
  EXPECT_NE(refusal<2>({{0, 0}, {1, 0}, {nan, 1}}).find("the 3rd point"), std::string::npos);
  EXPECT_NE(refusal<3>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, inf}}).find("not finite"),
            std::string::npos);
}

TEST(Bad_input, Duplicates) {
  EXPECT_NE(
      refusal<2>({{0, 0}, {1, 0}, {0, 1}, {1, 0}}).find("the 4th point duplicates the 2nd point"),
      std::string::npos);
  // Found by the triangulation (the repeat adds no vertex), named as the sorted points name it:
  // the first repeated point in their order, whatever the method and wherever the repeat lies.
  const std::vector<Point<3>> repeats = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2},
                                         {1, 1, 1}, {2, 0, 0}, {0, 0, 0}};
  for (Method method : {Method::robust, Method::paper, Method::cocone}) {
    Options options;
    options.method = method;
    EXPECT_NE(refusal<3>(repeats, options).find("the 7th point duplicates the 1st point"),
              std::string::npos)
        << to_string(method);
  }
  try {
    reconstruct(repeats);
    ADD_FAILURE() << "accepted";
  } catch (const Duplicate_points&) {
  }
}

// One stray point 300 orders of magnitude out: the refusal names it, not the first ordinary
// point measured against it.
TEST(Bad_input, ASetSpreadBeyondOneScaleNamesItsFarthestPoint) {
  std::vector<Point<3>> points = {{0.1, 0.2, 0.3}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  points.push_back({1e300, 0.5, 0.5});
  const std::string refused = refusal<3>(points);
  EXPECT_NE(refused.find("the 6th point (1.0000000000000001e+300, 0.5, 0.5)"), std::string::npos)
      << refused;
  EXPECT_NE(refused.find("orders of magnitude"), std::string::npos) << refused;
}

TEST(Bad_input, DegenerateSets) {
  EXPECT_NE(refusal<2>({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).find("collinear"), std::string::npos);
  EXPECT_NE(refusal<3>({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {2, 3, 1}}).find("coplanar"),
            std::string::npos);
  EXPECT_NE(refusal<3>({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).find("coplanar"),
            std::string::npos);
  // One point given again and again is named as such, not as a plane or a line.
  const std::vector<Point<3>> same(10, Point<3>{0.5, 2, -1});
  EXPECT_NE(refusal<3>(same).find("all 10 points are the same point (0.5, 2, -1)"),
            std::string::npos)
      << refusal<3>(same);
  EXPECT_NE(refusal<2>(std::vector<Point<2>>(5, Point<2>{1, 1})).find("all 5 points are the same"),
            std::string::npos);
}

TEST(Bad_input, Options) {
  Options options;
  options.box_factor = 0.5;
  EXPECT_NE(refusal<2>({{0, 0}, {1, 0}, {0, 1}}, options).find("box factor"), std::string::npos);
  options.box_factor = Options{}.box_factor;
  options.kind = Surface_kind::bordered;
  options.bordered_seed_sample = 10;
  EXPECT_NE(refusal<2>({{0, 0}, {1, 0}, {0, 1}}, options).find("not a sample"), std::string::npos);
}

TEST(Bad_input, SmallestValidInputsWork) {
  EXPECT_EQ(reconstruct(std::vector<Point<2>>{{0, 0}, {1, 0}, {0, 1}}).stats.facets, 3u);
  EXPECT_EQ(
      reconstruct(std::vector<Point<3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}).stats.facets,
      4u);
}

}  // namespace
}  // namespace sculpt
