// SPDX-License-Identifier: GPL-3.0-or-later
// Files for the io and command-line tests, in a folder of the build tree.
#pragma once

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

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace sculpt::testing
