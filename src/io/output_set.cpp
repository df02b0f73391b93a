// SPDX-License-Identifier: GPL-3.0-or-later
#include "output_set.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io_error.hpp"
#include "point_reader.hpp"
#include "temporary_files.hpp"

namespace sculpt::io {

void check_output_folder(const std::string& path) {
  const auto folder = std::filesystem::path(path).parent_path();
  if (!path.empty() && !folder.empty() && !std::filesystem::is_directory(folder)) {
    throw Error("cannot write '" + path + "': there is no folder '" + folder.string() + "'");
  }
}

std::string Output_set::stage(const std::string& destination) {
  const std::filesystem::path path(destination);
  const std::string extension = extension_of(destination);
  const std::string stem = path.stem().string();
  const auto temporary_for = [&](const std::string& ext) {
    return (path.parent_path() / ("." + stem + ".sculpt-" + std::to_string(::getpid()) + ext))
        .string();
  };
  const auto add = [&](const std::string& ext) {
    const std::string temporary = temporary_for(ext);
    register_temporary(temporary);
    staged_.emplace_back(temporary, (path.parent_path() / (stem + ext)).string());
    return temporary;
  };
  if (extension == ".node" || extension == ".ele") {
    add(extension == ".node" ? ".ele" : ".node");
  }
  return add(path.extension().string());
}

void Output_set::commit() {
  // A signal between two renames would leave some outputs and not others: it waits until all
  // are in place (and then ends the run, with every output written).
  sigset_t stopping, previous;
  sigemptyset(&stopping);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stopping, signal);
  pthread_sigmask(SIG_BLOCK, &stopping, &previous);
  for (const auto& [temporary, destination] : staged_) {
    if (std::rename(temporary.c_str(), destination.c_str()) != 0) {
      const int error = errno;
      pthread_sigmask(SIG_SETMASK, &previous, nullptr);
      throw Error("cannot write '" + destination + "': " + std::strerror(error));
    }
    forget_temporary(temporary);
  }
  committed_ = true;
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

Output_set::~Output_set() {
  if (committed_) return;
  for (const auto& staged : staged_) {
    std::remove(staged.first.c_str());
    forget_temporary(staged.first);
  }
}

}  // namespace sculpt::io
