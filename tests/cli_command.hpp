// SPDX-License-Identifier: GPL-3.0-or-later
// Runs the `sculpt` command as a user would, for the command-line tests: its exit code and what
// it printed.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "file_support.hpp"

namespace sculpt::testing {

struct Command_result {
  int exit_code;
  std::string out, err;
};

inline Command_result run_sculpt(const std::string& arguments) {
  // ctest runs tests in parallel processes: each run gets files of its own.
  static int runs = 0;
  const std::string stem = "cli-" + std::to_string(::getpid()) + "-" + std::to_string(runs++);
  const std::string out = output_path(stem + ".stdout"), err = output_path(stem + ".stderr");
  const std::string command =
      std::string(SCULPT_EXECUTABLE) + " " + arguments + " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
}

}  // namespace sculpt::testing
