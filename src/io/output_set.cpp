// SPDX-License-Identifier: GPL-3.0-or-later
#include "output_set.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io_error.hpp"
#include "point_reader.hpp"
#include "temporary_files.hpp"

namespace sculpt::io {
namespace {

bool is_tetgen(const std::string& extension) {
  return extension == ".node" || extension == ".ele";
}

std::string companion_extension(const std::string& extension) {
  return extension == ".node" ? ".ele" : ".node";
}

}  // namespace

std::vector<std::string> with_companions(std::vector<std::string> paths) {
  const std::size_t given = paths.size();
  for (std::size_t i = 0; i < given; ++i) {
    if (is_tetgen(extension_of(paths[i]))) {
      paths.push_back(std::filesystem::path(paths[i])
                          .replace_extension(companion_extension(extension_of(paths[i])))
                          .string());
    }
  }
  return paths;
}

std::string Output_set::stage(const std::string& destination) {
  const std::string temporary = make_temporary(destination);
  staged_.emplace_back(temporary, destination);
  const std::string extension = extension_of(destination);
  if (is_tetgen(extension)) {
    // The writer names the companion after the temporary: same stem, the other extension.
    const auto other = companion_extension(extension);
    const std::string companion = std::filesystem::path(temporary).replace_extension(other);
    register_temporary(companion, std::filesystem::path(destination).replace_extension(other));
    staged_.emplace_back(companion,
                         std::filesystem::path(destination).replace_extension(other).string());
  }
  return temporary;
}

void Output_set::commit() {
  // Every file written before any is renamed: an output its writer never made (a bug, a file
  // removed meanwhile) fails the set while nothing is in place yet.
  for (const auto& [temporary, destination] : staged_) {
    struct stat status {};
    if (::stat(temporary.c_str(), &status) != 0) {
      throw Error("cannot write '" + destination + "': it was not written");
    }
  }
  // A signal between two renames would leave some outputs and not others: it waits until all
  // are in place (and then ends the run, with every output written).
  sigset_t stopping, previous;
  sigemptyset(&stopping);
  add_ending_signals(stopping);
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
