// Running the viewer in a virtual X display (Xvfb), driven by a script (src/viewer/script.hpp).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

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
  const int code =
      run("xvfb-run -a -s '-screen 0 1280x1024x24' " + std::string(SCULPT_VIEW_EXECUTABLE) + " " +
          arguments + " --script " + path + " >" + log + " 2>&1");
  if (code != 0) std::cerr << read_file(log);
  return code;
}

}  // namespace sculpt::testing
