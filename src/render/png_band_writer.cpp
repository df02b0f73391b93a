// SPDX-License-Identifier: GPL-3.0-or-later
#include "png_band_writer.hpp"

#include <cstdlib>
#include <stdexcept>

#include "io/io_error.hpp"

namespace sculpt::render {
namespace {

constexpr std::size_t compressed_chunk = 1 << 16;  // bytes per IDAT chunk

void put_big_endian(unsigned char* out, std::uint32_t value) {
  out[0] = value >> 24;
  out[1] = value >> 16;
  out[2] = value >> 8;
  out[3] = value;
}

// The PNG predictor of Paeth: of left, up and up-left, the one nearest left + up - up-left.
int paeth(int left, int up, int up_left) {
  const int estimate = left + up - up_left;
  const int to_left = std::abs(estimate - left), to_up = std::abs(estimate - up),
            to_up_left = std::abs(estimate - up_left);
  if (to_left <= to_up && to_left <= to_up_left) return left;
  return to_up <= to_up_left ? up : up_left;
}

// One row filtered the five ways of the PNG standard; the one whose bytes, read as signed,
// sum to the least is kept (the heuristic the standard recommends), its type byte first.
void filter_row(const unsigned char* row, const unsigned char* above, std::size_t size,
                std::vector<unsigned char>& best) {
  std::vector<unsigned char> candidate(size + 1);
  long best_cost = -1;
  for (int type = 0; type < 5; ++type) {
    candidate[0] = static_cast<unsigned char>(type);
    long cost = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const int left = i >= 4 ? row[i - 4] : 0, up = above[i], up_left = i >= 4 ? above[i - 4] : 0;
      const int predicted = type == 0   ? 0
                            : type == 1 ? left
                            : type == 2 ? up
                            : type == 3 ? (left + up) / 2
                                        : paeth(left, up, up_left);
      const auto value = static_cast<unsigned char>(row[i] - predicted);
      candidate[i + 1] = value;
      cost += value < 128 ? value : 256 - value;
    }
    if (best_cost < 0 || cost < best_cost) {
      best_cost = cost;
      best.swap(candidate);
      candidate.resize(size + 1);
    }
  }
}

}  // namespace

Png_band_writer::Png_band_writer(const std::string& path, int width, int height)
    : file_(path, true), width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("a PNG needs a size above 0");
  if (deflateInit(&zlib_, Z_DEFAULT_COMPRESSION) != Z_OK) throw std::bad_alloc();
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  file_.stream().write(reinterpret_cast<const char*>(signature), 8);
  unsigned char header[13] = {};
  put_big_endian(header, static_cast<std::uint32_t>(width));
  put_big_endian(header + 4, static_cast<std::uint32_t>(height));
  header[8] = 8;  // bits per channel
  header[9] = 6;  // RGBA; compression, filtering and interlacing 0: the only methods defined
  write_chunk("IHDR", header, sizeof header);
  previous_row_.assign(4 * std::size_t(width), 0);  // the row above the first counts as zeros
  compressed_.resize(compressed_chunk);
}

Png_band_writer::~Png_band_writer() {
  deflateEnd(&zlib_);
}

void Png_band_writer::add(const Image& band) {
  if (band.width != width_ || rows_ + band.height > height_) {
    throw std::logic_error("a band that does not fit the PNG being written");
  }
  const std::size_t row_bytes = 4 * std::size_t(width_);
  for (int y = 0; y < band.height; ++y) {
    const unsigned char* row = band.pixel(0, y);
    filter_row(row, previous_row_.data(), row_bytes, filtered_);
    compress(filtered_.data(), filtered_.size(), Z_NO_FLUSH);
    previous_row_.assign(row, row + row_bytes);
  }
  rows_ += band.height;
}

void Png_band_writer::finish() {
  if (rows_ != height_) throw std::logic_error("a PNG finished before its last row");
  compress(nullptr, 0, Z_FINISH);
  write_chunk("IEND", nullptr, 0);
  file_.commit();
}

void Png_band_writer::compress(const unsigned char* data, std::size_t size, int flush) {
  zlib_.next_in = const_cast<unsigned char*>(data);
  zlib_.avail_in = static_cast<uInt>(size);
  for (;;) {
    zlib_.next_out = compressed_.data();
    zlib_.avail_out = static_cast<uInt>(compressed_.size());
    const int status = deflate(&zlib_, flush);
    if (status == Z_STREAM_ERROR) throw std::logic_error("zlib refused its stream");
    const std::size_t made = compressed_.size() - zlib_.avail_out;
    if (made > 0) write_chunk("IDAT", compressed_.data(), made);
    // Done when zlib has taken every byte and had room to spare, or ended the stream.
    if (flush == Z_FINISH ? status == Z_STREAM_END : zlib_.avail_out != 0) break;
  }
}

void Png_band_writer::write_chunk(const char type[4], const unsigned char* data, std::size_t size) {
  unsigned char length[4], check[4];
  put_big_endian(length, static_cast<std::uint32_t>(size));
  uLong crc = crc32(0, reinterpret_cast<const Bytef*>(type), 4);
  if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));
  put_big_endian(check, static_cast<std::uint32_t>(crc));
  std::ostream& out = file_.stream();
  out.write(reinterpret_cast<const char*>(length), 4);
  out.write(type, 4);
  if (size > 0) out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.write(reinterpret_cast<const char*>(check), 4);
}

}  // namespace sculpt::render
