// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for one point reader (SCULPT_FUZZ_FORMAT: ".ply", ".off", ...): see
// check_reader in fuzz_checks.hpp.
#include <cstdlib>
#include <iostream>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem = sculpt::fuzz::check_reader(
      std::string_view(reinterpret_cast<const char*>(data), size), SCULPT_FUZZ_FORMAT);
  if (!problem.empty()) {
    std::cerr << problem << '\n';
    std::abort();
  }
  return 0;
}
