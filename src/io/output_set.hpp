// SPDX-License-Identifier: GPL-3.0-or-later
// The outputs of one run, written all or none. Each output is written under a temporary name
// beside its destination (io/temporary_files.hpp); commit() renames them all into place once
// every one was written. An error, or leaving without commit, removes the temporaries, so a
// failed run leaves no output, new or half-written.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sculpt::io {

// The files that writing `paths` makes: a TetGen solid's .node brings its .ele and the other way
// round. What io::check_destinations must check before the work.
std::vector<std::string> with_companions(std::vector<std::string> paths);

class Output_set {
 public:
  Output_set() = default;
  ~Output_set();
  Output_set(const Output_set&) = delete;
  Output_set& operator=(const Output_set&) = delete;

  // The path to write `destination` to. A TetGen solid (.node or .ele) is staged with its
  // companion file, which its writer writes beside it.
  std::string stage(const std::string& destination);

  // Renames every staged file into place, with the signals that would end the run held until
  // the last is in place; throws io::Error if one cannot be (one that is a folder by now).
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // temporary, destination
  bool committed_ = false;
};

}  // namespace sculpt::io
