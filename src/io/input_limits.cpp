// SPDX-License-Identifier: GPL-3.0-or-later
#include "input_limits.hpp"

#include <climits>
#include <cstdint>
#include <cstdlib>

#include "io_error.hpp"

namespace sculpt::io {
namespace {

std::uint64_t from_environment(const char* variable, std::uint64_t fallback,
                               std::uint64_t largest) {
  const char* text = std::getenv(variable);
  if (!text || !*text) return fallback;
  std::uint64_t value = 0;
  for (const char* c = text; *c; ++c) {
    const bool digit = *c >= '0' && *c <= '9';
    if (!digit || value > (UINT64_MAX - 9) / 10) {
      throw Error(std::string(variable) + " must be a whole number above zero, not '" + text + "'");
    }
    value = value * 10 + std::uint64_t(*c - '0');
  }
  if (value == 0) throw Error(std::string(variable) + " must be a whole number above zero, not 0");
  if (value > largest) {
    throw Error(std::string(variable) + " must be at most " + std::to_string(largest) + ", not " +
                text);
  }
  return value;
}

}  // namespace

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t(1) << 30)) return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::uint64_t(1) << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

Input_limits input_limits() {
  Input_limits limits;
  limits.bytes = from_environment("SCULPT_MAX_INPUT_BYTES", limits.bytes, UINT64_MAX);
  // Points and faces are numbered with int (the readers, the triangulations' indices).
  limits.points = from_environment("SCULPT_MAX_POINTS", limits.points, INT_MAX);
  return limits;
}

std::string points_limit_text(std::uint64_t points) {
  return "the input limit of " + std::to_string(points) + " points (SCULPT_MAX_POINTS raises it)";
}

std::string bytes_limit_text(std::uint64_t bytes) {
  return "the input limit of " + size_text(bytes) + " (SCULPT_MAX_INPUT_BYTES raises it)";
}

}  // namespace sculpt::io
