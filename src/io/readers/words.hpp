// SPDX-License-Identifier: GPL-3.0-or-later
// Words and numbers of text formats, read strictly: a number is a whole word, a count is
// digits only, and anything quoted back to the user is made printable first.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sculpt::io {

// A word of an input as it can be shown in a one-line message: control and non-ASCII bytes
// as \xNN, long words cut.
std::string printable(std::string_view word, std::size_t max_length = 40);

// Splits at spaces, tabs, carriage returns, form feeds, vertical tabs and any of the extra
// separators.
void split_words(std::string_view line, std::vector<std::string_view>& words,
                 std::string_view extra_separators = {});

// A decimal number in any common spelling (1, -2.5, +3e4, nan, inf, infinity, any case);
// false if the word is not one. Values beyond the range of double become ±inf, as strtod does.
bool parse_number(std::string_view word, double& value);

// A count or index: decimal digits only (an optional '+'), at most 2^63 - 1.
bool parse_count(std::string_view word, std::uint64_t& value);
// A signed integer: an optional sign, then decimal digits; within int64.
bool parse_integer(std::string_view word, std::int64_t& value);

// Case-insensitive equality of ASCII words.
bool same_word(std::string_view a, std::string_view b);

}  // namespace sculpt::io
