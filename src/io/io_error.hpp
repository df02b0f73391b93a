// SPDX-License-Identifier: GPL-3.0-or-later
// Everything the io layer can refuse: a file that is missing, unreadable, malformed, truncated,
// or in a format Sculpt does not know. The message is one line, ready for the user.
#pragma once

#include <stdexcept>

namespace sculpt::io {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sculpt::io
