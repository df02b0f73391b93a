// SPDX-License-Identifier: GPL-3.0-or-later
// `sculpt bench` and `sculpt compare` as a user runs them: each job measured in a process of its
// own, the methods tabled and drawn side by side, a reference mesh measured against, and bad
// requests refused before any work.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_command.hpp"
#include "file_support.hpp"

namespace sculpt {
namespace {

using testing::Command_result;
using testing::output_path;
using testing::read_file;
using testing::run_sculpt;
using testing::write_file;

TEST(Cli, BenchMeasuresEachJobInAProcessOfItsOwn) {
  const auto json = output_path("bench.json");
  const Command_result run =
      run_sculpt("bench --example sphere --example star --runs 2 --json " + json);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("x DT"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("CGAL adv. front"), std::string::npos) << run.out;
  const auto rows = nlohmann::json::parse(read_file(json));
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    SCOPED_TRACE(row["input"].get<std::string>());
    EXPECT_GT(double(row["delaunay_only"]["seconds"]), 0.0);
    EXPECT_GT(double(row["delaunay_only"]["process"]["peak_mib"]), 1.0);
    for (const char* method : {"paper", "robust"}) {
      const auto& measured = row["methods"][method];
      ASSERT_FALSE(measured.contains("error")) << measured;
      EXPECT_GT(double(measured["process"]["cpu_seconds"]), 0.0);
      EXPECT_GE(double(measured["process"]["cpu_seconds"]),
                double(measured["total_seconds"]) * 0.5);
      EXPECT_TRUE(measured["manifold"].get<bool>()) << measured["verdict"];
    }
  }
  EXPECT_TRUE(rows[0]["advancing_front"]["manifold"].get<bool>());  // the sphere
  EXPECT_FALSE(rows[1].contains("advancing_front"));                // a curve: no surface method
}

// A job judges its result against the input's mesh (the share of triangles reproduced) and
// reads the mesh's topology: work the measured run would not do, timed apart and taken off the
// process's time. Points without a mesh leave nothing to take off.
TEST(Cli, BenchTakesOffTheTimeSpentJudgingResults) {
  const auto mesh = output_path("judged-sphere.off"), json = output_path("judged.json");
  ASSERT_EQ(run_sculpt("reconstruct --example sphere -q -o " + mesh).exit_code, 0);
  const Command_result run =
      run_sculpt("bench " + mesh + " --example sphere --methods robust --runs 1 --json " + json);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = nlohmann::json::parse(read_file(json));
  ASSERT_EQ(rows.size(), 2u);
  const auto judging = [](const nlohmann::json& job) {
    return double(job["evaluation"]["wall_seconds"]);
  };
  const auto& with_mesh = rows[0];
  EXPECT_DOUBLE_EQ(double(with_mesh["methods"]["robust"]["reproduced"]), 1.0);
  EXPECT_GT(judging(with_mesh["methods"]["robust"]), 0.0);
  EXPECT_GT(judging(with_mesh["delaunay_only"]), 0.0);
  EXPECT_GT(judging(with_mesh["advancing_front"]), 0.0);
  const auto& without = rows[1];
  EXPECT_EQ(judging(without["methods"]["robust"]), 0.0);
  EXPECT_EQ(judging(without["delaunay_only"]), 0.0);
}

// A PNG's width and height, from its header.
std::pair<int, int> png_size(const std::string& path) {
  const std::string bytes = read_file(path);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
  const auto big_endian = [&](int at) {
    int value = 0;
    for (int k = 0; k < 4; ++k) value = value * 256 + static_cast<unsigned char>(bytes[at + k]);
    return value;
  };
  return {big_endian(16), big_endian(20)};
}

TEST(Cli, CompareTablesTheMethodsAndDrawsThemSideBySide) {
  const auto markdown = output_path("compare.md"), json = output_path("compare.json"),
             pictures = output_path("compare.png");
  const Command_result run = run_sculpt(
      "compare --example bumpy --methods robust,cocone,nn-crust --tile 160x120 --markdown " +
      markdown + " --json " + json + " --pictures " + pictures);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(markdown), run.out);
  EXPECT_NE(run.out.find("| input | n | method | seconds | × DT |"), std::string::npos);
  EXPECT_NE(run.out.find("| bumpy | 6000 | robust |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| bumpy | 6000 | cocone |"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("nn-crust |"), std::string::npos);  // curves only: no row
  const auto rows = nlohmann::json::parse(read_file(json));
  ASSERT_EQ(rows.size(), 1u);
  const auto& robust = rows[0]["methods"]["robust"];
  EXPECT_TRUE(robust["manifold"].get<bool>());
  EXPECT_EQ(robust["output_vertices"].get<int>(), 6000);
  EXPECT_GT(double(robust["process"]["cpu_seconds"]), 0.0);
  EXPECT_FALSE(robust.contains("hausdorff"));  // no reference for an example
  // One row of three tiles: robust, cocone, and nn-crust's samples saying it does not apply.
  EXPECT_EQ(png_size(pictures), std::make_pair(3 * 160, 120));
}

TEST(Cli, CompareMeasuresAgainstAReferenceMesh) {
  const auto mesh = output_path("bumpy_reference.off"), json = output_path("reference.json");
  ASSERT_EQ(run_sculpt("reconstruct --example bumpy -o " + mesh).exit_code, 0);
  // A mesh input is its own reference: the robust method gives it back exactly.
  const Command_result run =
      run_sculpt("compare " + mesh + " --methods robust,alpha-shape --json " + json);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto rows = nlohmann::json::parse(read_file(json));
  const auto& robust = rows[0]["methods"]["robust"];
  EXPECT_DOUBLE_EQ(double(robust["reproduced"]), 1.0);
  EXPECT_LT(double(robust["hausdorff"]), 1e-12);  // zero, but for rounding
  const auto& alpha = rows[0]["methods"]["alpha-shape"];
  EXPECT_LT(double(alpha["reproduced"]), 1.0);
  EXPECT_GT(double(alpha["hausdorff_per_diagonal"]), 0.0);
  EXPECT_NE(run.out.find("| 100.0% | 0.0000 |"), std::string::npos) << run.out;
  // The same mesh given as --reference of the example whose samples it was made from.
  const Command_result again = run_sculpt("compare --example bumpy --methods robust --reference " +
                                          mesh + " --json " + json);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  rows = nlohmann::json::parse(read_file(json));
  EXPECT_DOUBLE_EQ(double(rows[0]["methods"]["robust"]["reproduced"]), 1.0);
  EXPECT_LT(double(rows[0]["methods"]["robust"]["hausdorff"]), 1e-12);
}

TEST(Cli, CompareRefusesBadRequestsBeforeAnyWork) {
  const auto table = output_path("refused.md");
  for (const std::string& arguments :
       {"compare --example bumpy --example star --reference " + output_path("x.off"),
        "compare --example bumpy --markdown " + output_path("table.txt"),
        "compare --example bumpy --tile 0x10 --markdown " + table,
        "compare --example bumpy --methods sculpting --markdown " + table,
        "compare --example bumpy --closed --markdown " + table, std::string("compare")}) {
    SCOPED_TRACE(arguments);
    const Command_result run = run_sculpt(arguments);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(table));
  }
}

// Every method failing on every input compares nothing: the run fails in the words and with the
// hint `reconstruct` gives, and writes no table.
TEST(Cli, CompareFailsWhenNoMethodSucceeds) {
  const auto input =
      write_file("compare-repeats.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0\n1 1 1\n");
  const auto table = output_path("compare-repeats.md");
  std::filesystem::remove(table);
  const Command_result run =
      run_sculpt("compare " + input + " --methods robust,paper --markdown " + table);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("the 5th point duplicates the 2nd point"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--merge-duplicates"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(table));
  // With the repeats merged, the methods compare.
  const Command_result merged =
      run_sculpt("compare " + input + " --methods robust --merge-duplicates --markdown " + table);
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
}

// `compare --clean` cleans the samples for every method alike, and the verdict column says so.
TEST(Cli, CompareCleansTheSamplesForEveryMethod) {
  std::string points;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {  // a Fibonacci sphere, then three strays far outside it
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = 2.399963 * i;
    points += fmt::format("{} {} {}\n", r * std::cos(phi), r * std::sin(phi), z);
  }
  points += "1.6 0.1 0.2\n0.1 -1.7 0.3\n-0.2 0.1 1.8\n";
  const auto input = write_file("compare-strays.xyz", points);
  const auto json = output_path("compare-strays.json"), table = output_path("compare-strays.md");
  const Command_result run =
      run_sculpt("compare " + input + " --methods robust,cocone --clean outliers --json " + json +
                 " --markdown " + table);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = nlohmann::json::parse(read_file(json));
  for (const char* method : {"robust", "cocone"}) {
    const auto& s = rows[0]["methods"][method];
    EXPECT_EQ(s.value("outliers_removed", 0), 3) << method << ": " << s.dump();
  }
  const std::string markdown = read_file(table);
  const auto first = markdown.find("; 3 outliers removed");
  ASSERT_NE(first, std::string::npos) << markdown;
  EXPECT_NE(markdown.find("; 3 outliers removed", first + 1), std::string::npos) << markdown;
  // As given (the automatic cleaning leaves clean samples alone), the strays are on it.
  ASSERT_EQ(run_sculpt("compare " + input + " --methods robust --json " + json).exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(read_file(json))[0]["methods"]["robust"].value("cleaned", true),
            false);
}

}  // namespace
}  // namespace sculpt
