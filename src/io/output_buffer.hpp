// SPDX-License-Identifier: GPL-3.0-or-later
// Text and bytes gathered and handed to a stream a megabyte at a time: the writers format
// millions of numbers, and a stream call per number costs more than formatting it.
#pragma once

#include <fmt/format.h>

#include <cstring>
#include <ostream>

namespace sculpt::io {

class Output_buffer {
 public:
  explicit Output_buffer(std::ostream& out) : out_(out) {}
  ~Output_buffer() { flush(); }
  Output_buffer(const Output_buffer&) = delete;
  Output_buffer& operator=(const Output_buffer&) = delete;

  template <class... Args>
  void text(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
    flush_if_full();
  }
  // The text and a line end.
  template <class... Args>
  void line(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
    buffer_.push_back('\n');
    flush_if_full();
  }
  // A value's bytes as the host holds them.
  template <class T>
  void binary(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    buffer_.append(bytes, bytes + sizeof(T));
    flush_if_full();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  void flush_if_full() {
    if (buffer_.size() > (1u << 20)) flush();
  }

  std::ostream& out_;
  fmt::memory_buffer buffer_;
};

}  // namespace sculpt::io
