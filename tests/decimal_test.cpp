// SPDX-License-Identifier: GPL-3.0-or-later
// The readers' numbers in the browser: where the C++ library lacks the floating-point
// std::from_chars (Emscripten's libc++), io::decimal_from_chars_portable reads the same syntax
// to the same value. Checked here against the library's own from_chars, on tricky words and on
// many random doubles in every printf spelling.
#include "io/readers/decimal.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

namespace sculpt {
namespace {

void expect_same_reading(const std::string& word) {
  SCOPED_TRACE("'" + word + "'");
  double expected = 12345.0, actual = 12345.0;  // left as they are when nothing is read
  const char* first = word.data();
  const char* last = first + word.size();
  const auto want = std::from_chars(first, last, expected);
  const auto got = io::decimal_from_chars_portable(first, last, actual);
  EXPECT_EQ(got.ptr - first, want.ptr - first);
  EXPECT_EQ(int(got.ec), int(want.ec));
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(actual));
  } else {
    EXPECT_EQ(std::memcmp(&expected, &actual, sizeof(double)), 0) << expected << " " << actual;
  }
}

TEST(Decimal, ReadsWhatFromCharsReads) {
  for (const char* word : {"0",
                           "-0",
                           "1",
                           "-2.5",
                           "3.",
                           ".5",
                           "-.5",
                           ".",
                           "-",
                           "",
                           "+1",
                           " 1",
                           "1 ",
                           "1e5",
                           "1E-5",
                           "1e+5",
                           "1e",
                           "1e+",
                           "1e-",
                           "2.5e",
                           "7e3x",
                           "1x",
                           "x1",
                           "0x1p3",
                           "0x10",
                           "inf",
                           "-inf",
                           "INF",
                           "Infinity",
                           "-infinity",
                           "infinit",
                           "infx",
                           "nan",
                           "NaN",
                           "-nan",
                           "nan(123)",
                           "nan(abc_9)",
                           "nan(",
                           "nan()",
                           "nan(-)",
                           "1e400",
                           "-1e400",
                           "1e-400",
                           "4.9e-324",
                           "2.2250738585072014e-308",
                           "1.7976931348623157e308",
                           "0.1",
                           "123456789012345678901234567890",
                           "00012.50",
                           "1..2",
                           "1.2.3",
                           "--1",
                           "e5",
                           "1,5",
                           "١"}) {
    expect_same_reading(word);
  }
}

TEST(Decimal, ReadsRandomDoublesToTheSameBits) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-320, 300);
  char text[64];
  for (int i = 0; i < 20000; ++i) {
    const double value = mantissa(random) * std::pow(10.0, exponent(random));
    for (const char* format : {"%.17g", "%.6e", "%g", "%.3f", "%.25g"}) {
      std::snprintf(text, sizeof text, format, value);
      expect_same_reading(text);
    }
  }
}

}  // namespace
}  // namespace sculpt
