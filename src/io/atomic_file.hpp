// SPDX-License-Identifier: GPL-3.0-or-later
// An output file that appears completely or not at all: it is written beside its destination
// under a temporary name (io/temporary_files.hpp) and renamed over it only once everything was
// written. Given a temporary an Output_set staged, it writes that directly: the set renames it.
#pragma once

#include <fstream>
#include <string>

namespace sculpt::io {

class Atomic_file {
 public:
  // Throws io::Error naming the user's path if the file cannot be created.
  Atomic_file(const std::string& path, bool binary);
  ~Atomic_file();  // removes the temporary file unless committed
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // throws io::Error if anything failed (a full disk, a file-size limit)

 private:
  std::string path_, temporary_;
  bool staged_;  // `path_` is an Output_set's temporary: written in place, renamed by the set
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace sculpt::io
