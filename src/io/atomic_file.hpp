// SPDX-License-Identifier: GPL-3.0-or-later
// An output file that appears completely or not at all: it is written beside its destination
// under a temporary name and renamed over it only once everything was written.
#pragma once

#include <fstream>
#include <string>

namespace sculpt::io {

class Atomic_file {
 public:
  Atomic_file(const std::string& path, bool binary);
  ~Atomic_file();  // removes the temporary file unless committed
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // throws io::Error if anything failed

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace sculpt::io
