// SPDX-License-Identifier: GPL-3.0-or-later
#include "atomic_file.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io_error.hpp"
#include "temporary_files.hpp"

namespace sculpt::io {
namespace {

// The streams keep no error code: the usual causes, found afterwards, with the limit named.
std::string why_writing_stopped(const std::string& temporary) {
  struct stat file {};
  rlimit limit{};
  if (::stat(temporary.c_str(), &file) == 0 && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
      limit.rlim_cur != RLIM_INFINITY &&
      static_cast<rlim_t>(file.st_size) + 65536 >= limit.rlim_cur) {
    return "the file is too large for this process's file-size limit of " +
           std::to_string(limit.rlim_cur) + " bytes (ulimit -f)";
  }
  const std::string folder = std::filesystem::path(temporary).parent_path().string();
  struct statvfs disk {};
  if (::statvfs(folder.empty() ? "." : folder.c_str(), &disk) == 0 && disk.f_bavail == 0) {
    return "the disk is full";
  }
  return "";
}

}  // namespace

Atomic_file::Atomic_file(const std::string& path, bool binary)
    : path_(path), staged_(is_temporary(path)) {
  temporary_ = staged_ ? path : make_temporary(path);
  out_.open(temporary_, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!out_) {
    const int error = errno;
    if (!staged_) forget_temporary(temporary_);
    throw Error("cannot write '" + destination_of(path) + "': " + std::strerror(error));
  }
}

Atomic_file::~Atomic_file() {
  if (committed_ || staged_) return;  // a staged file is the set's to remove
  out_.close();
  std::remove(temporary_.c_str());
  forget_temporary(temporary_);
}

void Atomic_file::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) {
    const std::string why = why_writing_stopped(temporary_);
    throw Error("failed while writing '" + destination_of(path_) + "'" +
                (why.empty() ? "" : ": " + why));
  }
  if (staged_) {
    committed_ = true;
    return;
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw Error("cannot write '" + path_ + "': " + std::strerror(errno));
  }
  forget_temporary(temporary_);
  committed_ = true;
}

}  // namespace sculpt::io
