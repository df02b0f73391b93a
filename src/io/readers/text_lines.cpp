// SPDX-License-Identifier: GPL-3.0-or-later
#include "text_lines.hpp"

#include <algorithm>

#include "io/io_error.hpp"
#include "words.hpp"

namespace sculpt::io {

bool looks_binary(std::string_view bytes) {
  return std::any_of(bytes.begin(), bytes.end(), [](char byte) {
    const auto c = static_cast<unsigned char>(byte);
    return c == 0 || (c < 32 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v');
  });
}

Text_lines::Text_lines(Byte_input& input, const std::string& format, long first_line)
    : input_(input), number_(first_line) {
  if (looks_binary(input_.peek(4096))) {
    throw Error(input_.name() + " is not " + format + " (it holds binary data)");
  }
  input_.skip_byte_order_mark();
}

bool Text_lines::next(std::vector<std::string_view>& words, char comment,
                      std::string_view extra_separators) {
  if (!input_.read_line(line_)) return false;
  ++number_;
  if (looks_binary(line_)) throw Error(where() + " holds binary data");
  std::string_view content = line_;
  if (comment) content = content.substr(0, content.find(comment));
  split_words(content, words, extra_separators);
  return true;
}

std::string Text_lines::where() const {
  return input_.name() + " line " + std::to_string(number_);
}

}  // namespace sculpt::io
