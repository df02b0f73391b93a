// SPDX-License-Identifier: GPL-3.0-or-later
// Progress: every method runs the stages planned for it (so the overall progress crosses them
// all), and the overall fraction a caller sees only grows, from 0 to 1.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/stage_plan.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

template <int D>
void check_progress(const std::vector<Point<D>>& points, Surface_kind kind, bool keep) {
  for (Method method : testing::methods_in(D)) {
    const std::string name = to_string(method);
    Options options = testing::with_method(method);
    options.kind = kind;
    options.keep_triangulations = keep;
    std::vector<double> overall;
    options.progress = [&](const Progress& p) {
      overall.push_back(p.overall);
      return true;
    };
    const auto r = reconstruct(points, options);
    const std::string where = std::string(name) + " " + std::to_string(D) + "D " + to_string(kind) +
                              (keep ? " (triangulations kept)" : "");
    std::vector<std::string> planned, ran;
    for (const char* stage : planned_stages(options, D)) planned.push_back(stage);
    for (const auto& stage : r.stats.stages) ran.push_back(stage.name);
    EXPECT_EQ(ran, planned) << where;
    ASSERT_FALSE(overall.empty()) << where;
    EXPECT_EQ(overall.front(), 0.0) << where;
    EXPECT_DOUBLE_EQ(overall.back(), 1.0) << where;
    for (std::size_t i = 1; i < overall.size(); ++i)
      EXPECT_GE(overall[i], overall[i - 1]) << where << ", report " << i;
  }
}

TEST(Progress, EveryMethodRunsItsPlannedStagesAndTheOverallProgressOnlyGrows) {
  for (bool keep : {false, true}) {
    check_progress<2>(shapes::star(60).samples, Surface_kind::closed, keep);
    check_progress<2>(shapes::open_arc(40).samples, Surface_kind::bordered, keep);
    check_progress<3>(shapes::bumpy_sphere(600), Surface_kind::closed, keep);
    check_progress<3>(shapes::hemisphere(600), Surface_kind::bordered, keep);
  }
}

// The automatic kind runs closed, then maybe bordered: each run has half the bar, and a closed
// result kept jumps to the end; the bar still only grows, from 0 to 1.
template <int D>
void check_automatic_progress(const std::vector<Point<D>>& points, Surface_kind kept) {
  for (Method method : {Method::robust}) {  // the method that chooses
    Options options = testing::with_method(method);
    std::vector<double> overall;
    options.progress = [&](const Progress& p) {
      overall.push_back(p.overall);
      return true;
    };
    const auto r = reconstruct(points, options);
    SCOPED_TRACE(std::string(to_string(method)) + " " + std::to_string(D) + "D");
    EXPECT_EQ(r.stats.kind, kept);
    ASSERT_FALSE(overall.empty());
    EXPECT_EQ(overall.front(), 0.0);
    EXPECT_DOUBLE_EQ(overall.back(), 1.0);
    for (std::size_t i = 1; i < overall.size(); ++i) EXPECT_GE(overall[i], overall[i - 1]);
  }
}

TEST(Progress, TheAutomaticKindFillsTheBarOnce) {
  check_automatic_progress<2>(shapes::star(60).samples, Surface_kind::closed);
  check_automatic_progress<2>(shapes::open_arc(40).samples, Surface_kind::bordered);
  check_automatic_progress<3>(shapes::bumpy_sphere(600), Surface_kind::closed);
  check_automatic_progress<3>(shapes::hemisphere(1500), Surface_kind::bordered);
}

// The long stages of the peers report how far they are within the stage, not only at its start
// and end: CGAL's triangulations built point by point (the crust's, the power diagram), and the
// passes over the facets, triangles and cells after them.
TEST(Progress, TheLongStagesOfThePeersFillTheirBars) {
  const auto samples = shapes::sphere(12000);
  for (const auto& [method, stages] : std::vector<std::pair<Method, std::vector<std::string>>>{
           {Method::crust, {"crust", "pruning", "walk"}},
           {Method::tight_cocone, {"cocone", "pruning", "walk", "peeling"}},
           {Method::power_crust, {"power diagram", "power-crust"}}}) {
    Options options = testing::with_method(method);
    std::set<std::string> reported_within;
    options.progress = [&](const Progress& p) {
      EXPECT_TRUE(p.fraction >= 0 && p.fraction <= 1) << p.stage << " " << p.fraction;
      if (p.fraction > 0 && p.fraction < 1) reported_within.insert(p.stage);
      return true;
    };
    reconstruct(samples, options);
    for (const auto& stage : stages) {
      EXPECT_TRUE(reported_within.count(stage)) << to_string(method) << ": " << stage;
    }
  }
}

}  // namespace
}  // namespace sculpt
