// SPDX-License-Identifier: GPL-3.0-or-later
// Messages for a terminal or a log: whatever a message holds, one line.
#pragma once

#include <string>

namespace sculpt::frontend {

// A message as one line: newlines become "; ", other control bytes \xNN.
inline std::string one_line(const std::string& message) {
  std::string result;
  for (char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\r') {
      if (!result.empty() && result.back() != ' ') result += "; ";
    } else if (byte < 32 || byte == 127) {
      static const char* hex = "0123456789abcdef";
      result += std::string("\\x") + hex[byte >> 4] + hex[byte & 15];
    } else {
      result += c;
    }
  }
  while (!result.empty() && (result.back() == ' ' || result.back() == ';')) result.pop_back();
  return result;
}

}  // namespace sculpt::frontend
