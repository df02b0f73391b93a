// SPDX-License-Identifier: GPL-3.0-or-later
#include "destinations.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <utility>

#include "io_error.hpp"

namespace sculpt::io {
namespace {

namespace fs = std::filesystem;

// A file's identity: two names are the same file when they reach the same device and inode.
using File_identity = std::pair<dev_t, ino_t>;

std::optional<File_identity> identity_of(const std::string& path) {
  struct stat status {};
  if (path.empty() || ::stat(path.c_str(), &status) != 0) return std::nullopt;
  return File_identity{status.st_dev, status.st_ino};
}

std::mutex remembered_lock;
std::set<File_identity>& remembered_inputs() {
  static std::set<File_identity> inputs;
  return inputs;
}

std::string refusal(const std::string& path, const std::string& why) {
  return "cannot write '" + path + "': " + why;
}

// A name for comparing outputs that do not exist yet: absolute, `.` and `..` resolved, links
// followed as far as they exist.
std::string comparable_name(const std::string& path) {
  std::error_code error;
  const fs::path name = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal().string() : name.string();
}

}  // namespace

void check_destination(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) return;
  const fs::path folder = fs::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    throw Error(refusal(path, "there is no folder '" + folder.string() + "'"));
  }
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) throw Error(refusal(path, "it is a folder"));
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw Error(refusal(path,
                        "it is not a regular file (a pipe, a device or a socket); an "
                        "output replaces a file"));
  }
  const auto destination = identity_of(path);
  if (!destination) return;  // a new file: no input can be it, and nothing to keep
  for (const std::string& input : inputs) {
    if (identity_of(input) == destination) {
      throw Error(refusal(path, input == path ? "it is the input; an output never replaces an "
                                                "input (choose another name)"
                                              : "it is the input '" + input +
                                                    "'; an output never replaces an input "
                                                    "(choose another name)"));
    }
  }
  std::lock_guard<std::mutex> lock(remembered_lock);
  if (remembered_inputs().count(*destination) != 0) {
    throw Error(refusal(path,
                        "it was read as input; an output never replaces an input (choose "
                        "another name)"));
  }
  // A file made read-only is kept so on purpose: the output would replace it (a new file
  // renamed over it) where writing into it is refused, and root may write to it anyway.
  constexpr fs::perms writable =
      fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
  if ((status.permissions() & writable) == fs::perms::none || ::access(path.c_str(), W_OK) != 0) {
    throw Error(refusal(path,
                        "it is read-only; an output replaces a file only where it may be "
                        "written (choose another name, or make it writable)"));
  }
}

void check_destinations(const std::vector<std::string>& paths,
                        const std::vector<std::string>& inputs) {
  std::set<std::string> names;
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    check_destination(path, inputs);
    if (!names.insert(comparable_name(path)).second) {
      throw Error(refusal(path, "it is named twice among the outputs"));
    }
  }
}

void remember_input(const std::string& path) {
  if (const auto identity = identity_of(path)) {
    std::lock_guard<std::mutex> lock(remembered_lock);
    remembered_inputs().insert(*identity);
  }
}

}  // namespace sculpt::io
