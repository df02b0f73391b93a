// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the reconstruction on tiny inputs: see check_reconstruction in
// fuzz_checks.hpp.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sculpt::fuzz::check_reconstruction(data, size);
  return 0;
}
