// SPDX-License-Identifier: GPL-3.0-or-later
// The `sculpt` command run as a process of its own, for the tests of what a run leaves behind:
// in a folder, with a file-size limit, environment variables, or a signal sent while it runs.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "file_support.hpp"

namespace sculpt::testing {

struct Command_run {
  int exit_code = -1;  // -1: ended by a signal
  int signal = 0;
  std::string err;
};

struct Run_conditions {
  int signal = 0;  // sent `signal_after_ms` after the start
  int signal_after_ms = 0;
  long file_size_limit = -1;             // bytes (ulimit -f); -1: none
  std::vector<std::string> environment;  // "NAME=value"
};

// Runs `sculpt` with `arguments` in `folder`, stdout to /dev/null, stderr kept.
inline Command_run run_sculpt(const std::filesystem::path& folder,
                              const std::vector<std::string>& arguments,
                              const Run_conditions& conditions = {}) {
  const std::filesystem::path err_path =
      folder.parent_path() / (folder.filename().string() + ".stderr");
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(folder.c_str()) != 0) ::_exit(126);
    const int null = ::open("/dev/null", O_WRONLY);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(null, 1);
    ::dup2(err, 2);
    if (conditions.file_size_limit >= 0) {
      const rlimit limit{static_cast<rlim_t>(conditions.file_size_limit),
                         static_cast<rlim_t>(conditions.file_size_limit)};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    for (const auto& assignment : conditions.environment)
      ::putenv(const_cast<char*>(assignment.c_str()));
    std::vector<char*> argv{const_cast<char*>("sculpt")};
    for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    ::execv(SCULPT_EXECUTABLE, argv.data());
    ::_exit(127);
  }
  if (conditions.signal != 0) {
    ::usleep(conditions.signal_after_ms * 1000);
    ::kill(child, conditions.signal);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  Command_run run;
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  run.err = read_file(err_path.string());
  return run;
}

inline std::vector<std::string> names_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

inline int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace sculpt::testing
