// SPDX-License-Identifier: GPL-3.0-or-later
// How a refusal names a point of the input: by its place, counted from 1, and its coordinates
// in full.
#pragma once

#include <sculpt/sculpt.hpp>
#include <sstream>
#include <string>

namespace sculpt {

// A point named by its place in the input, counted from 1 as a reader of the file counts and as
// an ordinal says ("the 796th point": the line a one-point-a-line file holds it on, index 795).
inline std::string ordinal_point(std::size_t index) {
  const std::size_t n = index + 1;
  const char* suffix = (n % 100 >= 11 && n % 100 <= 13) ? "th"
                       : n % 10 == 1                    ? "st"
                       : n % 10 == 2                    ? "nd"
                       : n % 10 == 3                    ? "rd"
                                                        : "th";
  return "the " + std::to_string(n) + suffix + " point";
}

template <int D>
std::string describe_point(const Point<D>& p) {
  std::ostringstream out;
  out.precision(17);
  out << '(';
  for (int k = 0; k < D; ++k) out << (k ? ", " : "") << p[k];
  out << ')';
  return out.str();
}

}  // namespace sculpt
