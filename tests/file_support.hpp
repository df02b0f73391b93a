// SPDX-License-Identifier: GPL-3.0-or-later
// Files for the io and command-line tests, in a folder of the build tree.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sculpt::testing {

inline std::string output_path(const std::string& name) {
  std::filesystem::create_directories(SCULPT_TEST_OUTPUT);
  const std::string path = std::string(SCULPT_TEST_OUTPUT) + "/" + name;
  std::filesystem::remove(path);
  return path;
}

// An empty folder below the test output, made afresh for one test.
inline std::filesystem::path fresh_folder(const std::string& relative) {
  const std::filesystem::path path = std::filesystem::path(SCULPT_TEST_OUTPUT) / relative;
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

inline std::string write_file(const std::string& name, const std::string& content) {
  const std::string path = output_path(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// n points spread evenly on the unit sphere (a Fibonacci sphere), "x y z" per line, as .xyz.
inline std::string sphere_points_text(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    text += fmt::format("{:.17g} {:.17g} {:.17g}\n", r * std::cos(a), r * std::sin(a), z);
  }
  return text;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace sculpt::testing
