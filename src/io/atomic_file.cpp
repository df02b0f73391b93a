// SPDX-License-Identifier: GPL-3.0-or-later
#include "atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io_error.hpp"
#include "temporary_files.hpp"

namespace sculpt::io {

Atomic_file::Atomic_file(const std::string& path, bool binary)
    : path_(path), temporary_(path + ".partial-" + std::to_string(::getpid())) {
  register_temporary(temporary_);
  out_.open(temporary_, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!out_) throw Error("cannot write '" + path + "': " + std::strerror(errno));
}

Atomic_file::~Atomic_file() {
  if (!committed_) {
    out_.close();
    std::remove(temporary_.c_str());
  }
  forget_temporary(temporary_);
}

void Atomic_file::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) throw Error("failed while writing '" + path_ + "'");
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw Error("cannot write '" + path_ + "': " + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace sculpt::io
