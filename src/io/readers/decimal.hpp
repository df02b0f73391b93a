// SPDX-License-Identifier: GPL-3.0-or-later
// A double read as std::from_chars reads it (its general format: an optional '-', digits with an
// optional point, an optional exponent; inf, infinity, nan, nan(chars) in any case; nothing
// before or after). Where the C++ library lacks the floating-point from_chars (Emscripten's
// libc++ 14 has only the integer ones), the same syntax is checked here and the value computed
// by strtod, correctly rounded as from_chars is: a file reads the same in the browser.
#pragma once

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace sculpt::io {

namespace decimal_detail {

inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// The word `word` (lower case) at p, in any case.
inline bool starts_with_word(const char* p, const char* last, const char* word) {
  for (; *word; ++word, ++p) {
    if (p == last || (*p | 0x20) != *word) return false;
  }
  return true;
}

}  // namespace decimal_detail

inline std::from_chars_result decimal_from_chars_portable(const char* first, const char* last,
                                                          double& value) {
  using namespace decimal_detail;
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const char* stop = nullptr;
  if (starts_with_word(p, last, "infinity")) {
    stop = p + 8;
  } else if (starts_with_word(p, last, "inf")) {
    stop = p + 3;
  } else if (starts_with_word(p, last, "nan")) {
    stop = p + 3;
    // nan(chars): letters, digits and underscores in parentheses, else just nan.
    if (stop != last && *stop == '(') {
      const char* q = stop + 1;
      while (q != last && (is_digit(*q) || ((*q | 0x20) >= 'a' && (*q | 0x20) <= 'z') || *q == '_'))
        ++q;
      if (q != last && *q == ')') stop = q + 1;
    }
  } else {
    const char* q = p;
    std::size_t digits = 0;
    while (q != last && is_digit(*q)) ++q, ++digits;
    if (q != last && *q == '.') {
      ++q;
      while (q != last && is_digit(*q)) ++q, ++digits;
    }
    if (digits == 0) return {first, std::errc::invalid_argument};
    stop = q;
    // An exponent only where digits follow it; else the number ends before the 'e'.
    if (q != last && (*q == 'e' || *q == 'E')) {
      ++q;
      if (q != last && (*q == '+' || *q == '-')) ++q;
      if (q != last && is_digit(*q)) {
        while (q != last && is_digit(*q)) ++q;
        stop = q;
      }
    }
  }
  const std::string text(first, stop);
  errno = 0;
  const double read = std::strtod(text.c_str(), nullptr);
  // Out of range: beyond the largest double, or below the smallest denormal (a denormal itself
  // is read, as from_chars does, though strtod flags it too).
  if (errno == ERANGE && (std::isinf(read) || read == 0))
    return {stop, std::errc::result_out_of_range};
  value = read;
  return {stop, std::errc()};
}

inline std::from_chars_result decimal_from_chars(const char* first, const char* last,
                                                 double& value) {
#if defined(__cpp_lib_to_chars)
  return std::from_chars(first, last, value);
#else
  return decimal_from_chars_portable(first, last, value);
#endif
}

}  // namespace sculpt::io
