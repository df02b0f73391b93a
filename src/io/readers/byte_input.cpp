// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "io/io_error.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

constexpr std::size_t buffer_size = 1 << 20;

}  // namespace

Byte_input Byte_input::open_file(const std::string& path, const Input_limits& limits) {
  Byte_input input;
  input.name_ = "'" + printable(path, 1000) + "'";
  input.limit_ = limits.bytes;
  input.point_limit_ = limits.points;
  input.descriptor_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (input.descriptor_ < 0) {
    throw Error("cannot open " + input.name_ + ": " + std::strerror(errno));
  }
  struct stat status {};
  if (::fstat(input.descriptor_, &status) != 0) {
    throw Error("cannot read " + input.name_ + ": " + std::strerror(errno));
  }
  if (S_ISDIR(status.st_mode)) throw Error(input.name_ + " is a folder, not a point file");
  if (S_ISREG(status.st_mode)) {
    input.size_known_ = true;
    input.size_ = static_cast<std::uint64_t>(status.st_size);
    if (input.size_ > input.limit_) {
      throw Error(input.name_ + " holds " + size_text(input.size_) + ", more than " +
                  bytes_limit_text(input.limit_));
    }
  }
  input.buffer_.resize(buffer_size);
  input.data_ = input.buffer_.data();
  return input;
}

Byte_input Byte_input::from_memory(std::string_view bytes, std::string name, std::size_t chunk,
                                   std::uint64_t point_limit) {
  Byte_input input;
  input.point_limit_ = point_limit;
  if (chunk > 0) {
    input.name_ = std::move(name);
    input.size_known_ = true;
    input.size_ = input.limit_ = bytes.size();
    input.chunked_source_ = bytes;
    input.chunk_ = chunk;
    input.buffer_.resize(std::min<std::size_t>(buffer_size, 4 * chunk));
    input.data_ = input.buffer_.data();
    return input;
  }
  input.name_ = std::move(name);
  input.size_known_ = true;
  input.size_ = bytes.size();
  input.limit_ = bytes.size();
  input.data_ = bytes.data();
  input.end_ = bytes.size();
  input.exhausted_ = true;
  return input;
}

Byte_input::Byte_input(Byte_input&& other) noexcept
    : name_(std::move(other.name_)),
      descriptor_(other.descriptor_),
      chunked_source_(other.chunked_source_),
      chunk_(other.chunk_),
      size_(other.size_),
      size_known_(other.size_known_),
      limit_(other.limit_),
      point_limit_(other.point_limit_),
      buffer_(std::move(other.buffer_)),
      data_(other.data_),
      position_(other.position_),
      end_(other.end_),
      consumed_(other.consumed_),
      exhausted_(other.exhausted_) {
  if (!buffer_.empty()) data_ = buffer_.data();  // the buffer moved with its storage
  other.descriptor_ = -1;
}

Byte_input::~Byte_input() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

std::uint64_t Byte_input::remaining_bound() const {
  const std::uint64_t total = size_known_ ? size_ : limit_;
  return total > offset() ? total - offset() : 0;
}

void Byte_input::check_count(std::uint64_t count, std::uint64_t bytes_each,
                             const std::string& what) const {
  if (bytes_each == 0) bytes_each = 1;
  const std::uint64_t room = remaining_bound();
  // The last item of a text file may lack its line end: one byte of slack.
  if (count > (room + 1) / bytes_each) {
    throw Error(name_ + " is truncated or malformed: it announces " + std::to_string(count) + " " +
                what + ", but " + (size_known_ ? "only " : "at most ") + std::to_string(room) +
                " bytes can follow");
  }
}

void Byte_input::check_room_for_point(std::uint64_t points) const {
  if (points >= point_limit_) {
    throw Error(name_ + " holds more points than " + points_limit_text(point_limit_));
  }
}

void Byte_input::check_room_for_face(std::uint64_t faces) const {
  const std::uint64_t limit = Input_limits{0, point_limit_}.faces();
  if (faces >= limit) {
    throw Error(name_ + " holds more triangles than the input limit of " + std::to_string(limit) +
                " (four per point of SCULPT_MAX_POINTS, which raises it)");
  }
}

bool Byte_input::fill(std::size_t wanted) {
  if (end_ - position_ >= wanted) return true;
  if (exhausted_) return false;
  // Keep the unread bytes, at the front of the buffer.
  std::memmove(buffer_.data(), buffer_.data() + position_, end_ - position_);
  consumed_ += position_;
  end_ -= position_;
  position_ = 0;
  if (buffer_.size() < wanted) buffer_.resize(wanted);
  data_ = buffer_.data();
  while (end_ < wanted) {
    const std::size_t got = read_some(buffer_.data() + end_, buffer_.size() - end_);
    if (got == 0) {
      exhausted_ = true;
      break;
    }
    end_ += got;
    if (consumed_ + end_ > limit_) {
      throw Error(name_ + " is longer than " + bytes_limit_text(limit_));
    }
  }
  return end_ - position_ >= wanted;
}

std::size_t Byte_input::read_some(char* out, std::size_t capacity) {
  if (descriptor_ < 0) {
    const std::size_t n = std::min({capacity, chunk_, chunked_source_.size()});
    if (n > 0) std::memcpy(out, chunked_source_.data(), n);
    chunked_source_.remove_prefix(n);
    return n;
  }
  for (;;) {
    const ssize_t got = ::read(descriptor_, out, capacity);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR) throw Error("cannot read " + name_ + ": " + std::strerror(errno));
  }
}

std::string_view Byte_input::peek(std::size_t n) {
  fill(n);
  return {data_ + position_, std::min(n, end_ - position_)};
}

void Byte_input::read(void* out, std::size_t n, const char* what) {
  if (!fill(n)) {
    throw Error(name_ + " is truncated: it ends inside " + what + " (at byte " +
                std::to_string(offset() + (end_ - position_)) + ")");
  }
  std::memcpy(out, data_ + position_, n);
  position_ += n;
}

void Byte_input::skip_byte_order_mark() {
  if (peek(3) == "\xEF\xBB\xBF") position_ += 3;
}

bool Byte_input::read_line(std::string& line, std::size_t max_length) {
  // Lines end in "\n", "\r\n" or a lone "\r" (old Mac files).
  line.clear();
  bool any_byte = false;
  for (;;) {
    if (position_ == end_ && !fill(1)) return any_byte;
    const char* start = data_ + position_;
    const std::size_t available = end_ - position_;
    std::size_t taken = 0;
    while (taken < available && start[taken] != '\n' && start[taken] != '\r') ++taken;
    if (line.size() + taken > max_length) {
      throw Error(name_ + " has a line longer than " + size_text(max_length) +
                  " (is it a text file?)");
    }
    line.append(start, taken);
    position_ += taken;
    any_byte = true;
    if (taken < available) {
      const char end = data_[position_++];
      if (end == '\r' && fill(1) && data_[position_] == '\n') ++position_;
      return true;
    }
  }
}

}  // namespace sculpt::io
