// SPDX-License-Identifier: GPL-3.0-or-later
#include "words.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>

#include "decimal.hpp"

namespace sculpt::io {

std::string printable(std::string_view word, std::size_t max_length) {
  static const char* hex = "0123456789abcdef";
  std::string result;
  for (std::size_t i = 0; i < word.size() && i < max_length; ++i) {
    const auto c = static_cast<unsigned char>(word[i]);
    if (c >= 32 && c < 127) {
      result += static_cast<char>(c);
    } else {
      result += "\\x";
      result += hex[c >> 4];
      result += hex[c & 15];
    }
  }
  if (word.size() > max_length) result += "...";
  return result;
}

void split_words(std::string_view line, std::vector<std::string_view>& words,
                 std::string_view extra_separators) {
  words.clear();
  auto is_space = [extra_separators](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\n' ||
           extra_separators.find(c) != std::string_view::npos;
  };
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
}

bool parse_number(std::string_view word, double& value) {
  if (!word.empty() && word[0] == '+') {
    word.remove_prefix(1);
    if (!word.empty() && (word[0] == '-' || word[0] == '+')) return false;
  }
  if (word.empty()) return false;
  const char* end = word.data() + word.size();
  const auto [stop, error] = decimal_from_chars(word.data(), end, value);
  if (stop != end) return false;
  if (error == std::errc::result_out_of_range) {
    // Overflow to ±inf, underflow to a denormal or zero: what strtod gives.
    const std::string copy(word);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return error == std::errc();
}

bool parse_count(std::string_view word, std::uint64_t& value) {
  if (!word.empty() && word[0] == '+') word.remove_prefix(1);
  if (word.empty()) return false;
  for (char c : word) {
    if (c < '0' || c > '9') return false;
  }
  const auto [stop, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && stop == word.data() + word.size() &&
         value <= (std::uint64_t(1) << 63) - 1;
}

bool parse_integer(std::string_view word, std::int64_t& value) {
  const bool negative = !word.empty() && word[0] == '-';
  if (negative) word.remove_prefix(1);
  if (!word.empty() && (word[0] == '-' || (negative && word[0] == '+'))) return false;
  std::uint64_t magnitude = 0;
  if (!parse_count(word, magnitude)) return false;
  value = negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  return true;
}

bool same_word(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

}  // namespace sculpt::io
