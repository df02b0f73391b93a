// SPDX-License-Identifier: GPL-3.0-or-later
// A folder of outputs (the figures' gallery) that a run creates when it is missing and removes
// again, with any parents it had to create, when the run fails: with an io::Output_set for the
// files inside, a failed run leaves exactly what was there before, not an empty folder.
#pragma once

#include <string>
#include <vector>

namespace sculpt::io {

class Output_folder {
 public:
  // Throws io::Error, one line naming the path, if it is a file or cannot be created.
  explicit Output_folder(const std::string& path);
  ~Output_folder();  // unless kept: removes the folders it created, if they are still empty
  Output_folder(const Output_folder&) = delete;
  Output_folder& operator=(const Output_folder&) = delete;

  void keep() { kept_ = true; }

 private:
  void remove_created();

  std::vector<std::string> created_;  // outermost first
  bool kept_ = false;
};

}  // namespace sculpt::io
