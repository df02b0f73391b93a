// SPDX-License-Identifier: GPL-3.0-or-later
// The bytes of an input file, read through a bounded buffer: never more in memory than one
// buffer (and the line being read), never more read than a limit, and a count announced by a
// header can always be checked against the bytes that can still follow it. Regular files,
// pipes and memory (the fuzzers) look the same to the readers.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_limits.hpp"

namespace sculpt::io {

class Byte_input {
 public:
  // Opens a file; throws io::Error if it is missing, unreadable or a directory.
  static Byte_input open_file(const std::string& path, const Input_limits& limits);
  // Reads from memory that outlives the input. With a chunk size, the bytes are handed over
  // that many at a time, through the same buffer refills as a pipe (for the fuzzers and tests).
  static Byte_input from_memory(std::string_view bytes, std::string name, std::size_t chunk = 0,
                                std::uint64_t point_limit = Input_limits{}.points);

  Byte_input(Byte_input&&) noexcept;
  Byte_input& operator=(Byte_input&&) = delete;
  Byte_input(const Byte_input&) = delete;
  ~Byte_input();

  // The name used in messages: the path, quoted.
  const std::string& name() const { return name_; }
  std::uint64_t offset() const { return consumed_ + position_; }
  // At most this many bytes can still follow: exact for files and memory, the limit for pipes.
  std::uint64_t remaining_bound() const;
  // Throws io::Error unless `count` items of at least `bytes_each` bytes fit in what can follow.
  void check_count(std::uint64_t count, std::uint64_t bytes_each, const std::string& what) const;

  // The budget on points (io/input_limits.hpp): throws io::Error, naming the limit, unless a
  // reader that holds `points` points, or `faces` triangles, may read one more.
  void check_room_for_point(std::uint64_t points) const;
  void check_room_for_face(std::uint64_t faces) const;

  // The first up to n bytes of what is left, without consuming them; valid until the next
  // call (a refill may move or grow the buffer).
  std::string_view peek(std::size_t n);
  bool at_end() { return peek(1).empty(); }
  // Consumes a UTF-8 byte order mark if the input continues with one (editors on Windows).
  void skip_byte_order_mark();
  // Consumes exactly n bytes into out; throws io::Error (truncated) if fewer remain.
  void read(void* out, std::size_t n, const char* what);
  // The next line without its end ('\n', "\r\n"); false at the end of the input. Throws
  // io::Error for a line longer than max_length (a binary file read as text).
  bool read_line(std::string& line, std::size_t max_length = 1 << 20);

 private:
  Byte_input() = default;
  bool fill(std::size_t wanted);  // makes `wanted` bytes available if the input has them
  std::size_t read_some(char* out, std::size_t capacity);  // 0 at the end

  std::string name_;
  int descriptor_ = -1;
  std::string_view chunked_source_;  // a memory source handed over in chunks
  std::size_t chunk_ = 0;
  std::uint64_t size_ = 0;  // the whole input, when known
  bool size_known_ = false;
  std::uint64_t limit_ = 0;
  std::uint64_t point_limit_ = Input_limits{}.points;
  std::vector<char> buffer_;
  const char* data_ = nullptr;  // available bytes are data_[position_, end_)
  std::size_t position_ = 0, end_ = 0;
  std::uint64_t consumed_ = 0;  // bytes before data_[0]
  bool exhausted_ = false;
};

}  // namespace sculpt::io
