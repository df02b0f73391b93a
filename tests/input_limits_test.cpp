// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs read against a budget on bytes and one on points (io/input_limits.hpp): every format
// stops at the limit with one line that names it and the variable that raises it, an endless
// pipe of valid points ends in that line rather than in the memory running out, and the
// variables are read as what they say.
#include "io/input_limits.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "file_support.hpp"
#include "io/point_reader.hpp"
#include "sculpt_process.hpp"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

// Eleven points or so as every format writes them.
std::string eleven_points(const std::string& extension) {
  std::string vertices;
  for (int i = 0; i < 11; ++i) vertices += fmt::format("{} {} {}\n", i, i * i % 7, i % 3);
  if (extension == ".xyz") return vertices;
  if (extension == ".off") return "OFF\n11 1 0\n" + vertices + "3 0 1 2\n";
  if (extension == ".ply") {
    return "ply\nformat ascii 1.0\nelement vertex 11\nproperty float x\nproperty float y\n"
           "property float z\nend_header\n" +
           vertices;
  }
  if (extension == ".obj") {
    std::string obj;
    for (int i = 0; i < 11; ++i) obj += fmt::format("v {} {} {}\n", i, i * i % 7, i % 3);
    return obj;
  }
  // .stl: four triangles of distinct corners, twelve points.
  std::string stl = "solid s\n";
  for (int t = 0; t < 4; ++t) {
    stl += "facet normal 0 0 1\nouter loop\n";
    for (int c = 0; c < 3; ++c) stl += fmt::format("vertex {} {} {}\n", 3 * t + c, t, c);
    stl += "endloop\nendfacet\n";
  }
  return stl + "endsolid s\n";
}

TEST(Input_limits, EveryFormatStopsAtTheLimitOnPoints) {
  for (const std::string extension : {".xyz", ".off", ".ply", ".obj", ".stl"}) {
    SCOPED_TRACE(extension);
    const std::string path = testing::write_file("eleven" + extension, eleven_points(extension));
    const std::size_t points = io::read_points(path).points.size();
    EXPECT_GE(points, 11u);
    EXPECT_EQ(io::read_points(path, io::Input_limits{1 << 20, points}).points.size(), points);
    try {
      io::read_points(path, io::Input_limits{1 << 20, points - 1});
      ADD_FAILURE() << "read past the limit";
    } catch (const io::Error& e) {
      EXPECT_NE(std::string(e.what()).find(fmt::format(
                    "more points than the input limit of {} points (SCULPT_MAX_POINTS raises it)",
                    points - 1)),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(Input_limits, FacesAreBoundedFourPerPoint) {
  // Three points and thirteen faces over them: more than 4 x 3 triangles.
  std::string off = "OFF\n3 13 0\n0 0 0\n1 0 0\n0 1 0\n";
  for (int f = 0; f < 13; ++f) off += "3 0 1 2\n";
  const std::string path = testing::write_file("many-faces.off", off);
  EXPECT_NO_THROW(io::read_points(path, io::Input_limits{1 << 20, 4}));
  try {
    io::read_points(path, io::Input_limits{1 << 20, 3});
    ADD_FAILURE() << "read past the limit";
  } catch (const io::Error& e) {
    EXPECT_NE(std::string(e.what()).find("more triangles than the input limit of 12"),
              std::string::npos)
        << e.what();
  }
}

TEST(Input_limits, TheVariablesSayWhatTheyMean) {
  const io::Input_limits defaults;
  ::unsetenv("SCULPT_MAX_POINTS");
  ::unsetenv("SCULPT_MAX_INPUT_BYTES");
  EXPECT_EQ(io::input_limits().points, defaults.points);
  EXPECT_EQ(io::input_limits().bytes, defaults.bytes);
  ::setenv("SCULPT_MAX_POINTS", "123", 1);
  ::setenv("SCULPT_MAX_INPUT_BYTES", "4567", 1);
  EXPECT_EQ(io::input_limits().points, 123u);
  EXPECT_EQ(io::input_limits().bytes, 4567u);
  for (const char* wrong : {"12abc", "-5", "0", "1e6", "99999999999999999999999"}) {
    ::setenv("SCULPT_MAX_POINTS", wrong, 1);
    EXPECT_THROW(io::input_limits(), io::Error) << wrong;
  }
  ::unsetenv("SCULPT_MAX_POINTS");
  ::unsetenv("SCULPT_MAX_INPUT_BYTES");
  // A file beyond the byte limit is refused by its size, before a byte is read.
  const std::string path = testing::write_file("bytes.xyz", eleven_points(".xyz"));
  try {
    io::read_points(path, io::Input_limits{10, 100});
    ADD_FAILURE();
  } catch (const io::Error& e) {
    EXPECT_NE(std::string(e.what()).find("(SCULPT_MAX_INPUT_BYTES raises it)"), std::string::npos)
        << e.what();
  }
}

// A pipe that never ends, of points that are all valid: the budget ends the run, in one line.
TEST(Input_limits, AnEndlessPipeOfPointsEndsAtTheBudget) {
  const fs::path folder = testing::fresh_folder("input-limits/endless");
  ASSERT_EQ(::mkfifo((folder / "endless.xyz").c_str(), 0600), 0);
  const pid_t writer = ::fork();
  if (writer == 0) {
    ::signal(SIGPIPE, SIG_DFL);  // ends the writer once the reader is gone
    const int out = ::open((folder / "endless.xyz").c_str(), O_WRONLY);
    std::string block;
    for (int i = 0; i < 4096; ++i) block += fmt::format("{} {} {}\n", i % 61, i % 67, i);
    for (;;) {
      if (::write(out, block.data(), block.size()) < 0) ::_exit(0);
    }
  }
  const testing::Command_run run =
      testing::run_sculpt(folder, {"reconstruct", "endless.xyz", "-o", "s.off", "-q"},
                          {0, 0, -1, {"SCULPT_MAX_POINTS=200000"}});
  ::kill(writer, SIGKILL);
  ::waitpid(writer, nullptr, 0);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(testing::lines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("more points than the input limit of 200000 points (SCULPT_MAX_POINTS "
                         "raises it)"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(testing::names_in(folder), std::vector<std::string>{"endless.xyz"});
}

}  // namespace
}  // namespace sculpt
