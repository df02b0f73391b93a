// SPDX-License-Identifier: GPL-3.0-or-later
// Every input a fuzzer once failed on (fuzz/regressions/TARGET/), replayed through the same
// checks the fuzzers make, in every build: the sanitizer build catches what ASan caught then.
#include <gtest/gtest.h>

#include <filesystem>

#include "../fuzz/fuzz_checks.hpp"
#include "file_support.hpp"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> regressions(const std::string& target) {
  std::vector<fs::path> files;
  const fs::path folder = fs::path(SCULPT_FUZZ_DIR) / "regressions" / target;
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) files.push_back(entry.path());
  }
  return files;
}

TEST(Fuzz_regressions, ReadersAgreeAndRefuseInOneLine) {
  std::size_t replayed = 0;
  for (const std::string format : {"ply", "off", "obj", "stl", "xyz", "pts", "xy"}) {
    for (const auto& file : regressions("read_" + format)) {
      SCOPED_TRACE(file.string());
      EXPECT_EQ(fuzz::check_reader(testing::read_file(file.string()), "." + format), "");
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0u) << "fuzz/regressions holds the inputs that once crashed a reader";
}

TEST(Fuzz_regressions, ReconstructionOfTinyInputs) {
  for (const auto& file : regressions("reconstruct")) {
    SCOPED_TRACE(file.string());
    const std::string bytes = testing::read_file(file.string());
    fuzz::check_reconstruction(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  // The seeds too: every mode of the fuzzer on real shapes runs in the suite.
  for (const auto& entry :
       fs::directory_iterator(fs::path(SCULPT_FUZZ_DIR) / "corpus" / "reconstruct")) {
    const std::string bytes = testing::read_file(entry.path().string());
    fuzz::check_reconstruction(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
}

}  // namespace
}  // namespace sculpt
