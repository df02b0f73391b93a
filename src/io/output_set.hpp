// SPDX-License-Identifier: GPL-3.0-or-later
// The outputs of one run, written all or none. Each output is written under a temporary name
// beside its destination (same folder, same extension, so that writers choose the same format);
// commit() renames them all into place once every one was written. An error, or leaving without
// commit, removes the temporaries, so a failed run leaves no output, new or half-written.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sculpt::io {

// Throws io::Error if the folder an output would go into does not exist: checked for every
// output before any work, so a run never fails after it.
void check_output_folder(const std::string& path);

class Output_set {
 public:
  Output_set() = default;
  ~Output_set();
  Output_set(const Output_set&) = delete;
  Output_set& operator=(const Output_set&) = delete;

  // The path to write `destination` to. A TetGen solid (.node or .ele) is staged with its
  // companion file, which its writer writes beside it.
  std::string stage(const std::string& destination);

  // Renames every staged file into place; throws io::Error if one cannot be.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // temporary, destination
  bool committed_ = false;
};

}  // namespace sculpt::io
