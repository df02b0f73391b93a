// SPDX-License-Identifier: GPL-3.0-or-later
// The one line a failure is reported in, as `sculpt` prints it after "sculpt: ": the command
// line, the JavaScript module and the viewer in the browser say the same words.
#pragma once

#include <new>
#include <sculpt/sculpt.hpp>
#include <string>

#include "frontend/command_line_text.hpp"
#include "io/io_error.hpp"

namespace sculpt::frontend {

inline std::string failure_line(const std::exception& e) {
  if (dynamic_cast<const Duplicate_points*>(&e))
    return one_line(std::string("error: ") + e.what() +
                    " (--merge-duplicates removes repeated points)");
  if (dynamic_cast<const io::Error*>(&e) || dynamic_cast<const Input_error*>(&e))
    return one_line(std::string("error: ") + e.what());
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "error: out of memory";
  return one_line(std::string("internal error: ") + e.what());
}

}  // namespace sculpt::frontend
