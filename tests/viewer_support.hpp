// SPDX-License-Identifier: GPL-3.0-or-later
// Running the viewer in a virtual X display (Xvfb), driven by a script (src/viewer/script.hpp).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "file_support.hpp"

namespace sculpt::testing {

constexpr int panel_width = 360;  // the viewer's panel, on the left

inline int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs the viewer on a script in a virtual X display; returns its exit code.
inline int run_viewer_script(const std::string& name, const std::string& script,
                             const std::string& arguments = "") {
  if (run("command -v xvfb-run >/dev/null") != 0) {
    ADD_FAILURE() << "xvfb-run is missing: install xvfb and xauth (scripts/install-dependencies)";
    return -1;
  }
  const std::string path = write_file(name + ".script", script);
  const std::string log = output_path(name + ".log");
  // The viewer's own exit code, written by the shell inside xvfb-run: xvfb-run replaces it by 5
  // when it fails to clean up its temporary directory, which happens when tests run in parallel.
  const std::string code_file = output_path(name + ".exit-code");
  std::remove(code_file.c_str());
  const int xvfb_code = run("xvfb-run -a -s '-screen 0 1280x1024x24' sh -c '" +
                            std::string(SCULPT_VIEW_EXECUTABLE) + " " + arguments + " --script " +
                            path + "; echo $? >" + code_file + "' >" + log + " 2>&1");
  const std::string written = read_file(code_file);
  const int code = written.empty() ? xvfb_code : std::atoi(written.c_str());
  if (code != 0) std::cerr << read_file(log);
  return code;
}

}  // namespace sculpt::testing
