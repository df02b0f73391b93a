// SPDX-License-Identifier: GPL-3.0-or-later
// The lines of a text format (point lists, OFF, OBJ, ASCII PLY and STL bodies), numbered for
// messages. A file that holds binary bytes, or a line too long for text, is refused before it
// is read further; a UTF-8 byte order mark is skipped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "byte_input.hpp"

namespace sculpt::io {

// True if the bytes hold a NUL or a control character no text file has.
bool looks_binary(std::string_view bytes);

class Text_lines {
 public:
  // `format` names the format in the refusal of binary data ("a text point file").
  // Line numbers start after first_line (the lines of a header already read).
  Text_lines(Byte_input& input, const std::string& format, long first_line = 0);

  // The next line split into words after removing a `comment` character and what follows it
  // (none if 0); false at the end. Empty lines are returned too (no words).
  bool next(std::vector<std::string_view>& words, char comment,
            std::string_view extra_separators = {});
  // Where the current line is, for messages: "'path' line N".
  std::string where() const;
  const std::string& line() const { return line_; }
  Byte_input& input() { return input_; }

 private:
  Byte_input& input_;
  std::string line_;
  long number_ = 0;
};

}  // namespace sculpt::io
