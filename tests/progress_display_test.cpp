// SPDX-License-Identifier: GPL-3.0-or-later
// The command line's progress in a log (stderr not a terminal): one plain line per stage as it
// ends, with its time and the share of the run done, the last at 100%; nothing with -q, and
// nothing for a run too short to wonder about.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "file_support.hpp"
#include "sculpt_process.hpp"

namespace sculpt {
namespace {

TEST(Progress_display, ALogGetsALinePerStageWithItsTime) {
  const auto folder = testing::fresh_folder("progress-display");
  testing::write_file("progress-display/large.xyz", testing::sphere_points_text(25000));
  testing::write_file("progress-display/small.xyz", testing::sphere_points_text(2000));

  const testing::Command_run logged =
      testing::run_sculpt(folder, {"reconstruct", "large.xyz", "-o", "large.off"});
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  const std::regex line(
      R"(sculpt: ([a-z -]+) done in [0-9]+\.[0-9]{2} s \(([0-9]+)%(, about [0-9]+ (s|min) left)?\))");
  std::istringstream lines(logged.err);
  std::string text;
  int stages = 0, percent = -1;
  bool delaunay = false;
  while (std::getline(lines, text)) {
    std::smatch match;
    ASSERT_TRUE(std::regex_match(text, match, line)) << text;
    ++stages;
    delaunay = delaunay || match[1] == "delaunay";
    const int now = std::stoi(match[2]);
    EXPECT_GE(now, percent) << "the share done never goes back";
    percent = now;
  }
  EXPECT_GE(stages, 4) << logged.err;
  EXPECT_TRUE(delaunay) << logged.err;
  EXPECT_EQ(percent, 100) << logged.err;

  const testing::Command_run quiet =
      testing::run_sculpt(folder, {"reconstruct", "large.xyz", "-o", "quiet.off", "-q"});
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.err, "");
  const testing::Command_run small =
      testing::run_sculpt(folder, {"reconstruct", "small.xyz", "-o", "small.off"});
  EXPECT_EQ(small.exit_code, 0);
  EXPECT_EQ(small.err, "");
}

}  // namespace
}  // namespace sculpt
