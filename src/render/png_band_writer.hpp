// SPDX-License-Identifier: GPL-3.0-or-later
// A PNG written a band of rows at a time, so that a picture larger than memory should hold
// (compare's grid: a row of tiles per input) is composed and compressed band by band and never
// held whole. The file appears completely or not at all (io::Atomic_file).
#pragma once

#include <zlib.h>

#include <memory>
#include <string>
#include <vector>

#include "image.hpp"
#include "io/atomic_file.hpp"

namespace sculpt::render {

class Png_band_writer {
 public:
  // Throws io::Error if the file cannot be created, std::invalid_argument for a size of 0.
  Png_band_writer(const std::string& path, int width, int height);
  ~Png_band_writer();
  Png_band_writer(const Png_band_writer&) = delete;
  Png_band_writer& operator=(const Png_band_writer&) = delete;

  // The next rows, from the top: a band as wide as the picture.
  void add(const Image& band);
  int rows_written() const { return rows_; }
  // Ends the picture once every row was added; throws io::Error if writing failed.
  void finish();

 private:
  void write_chunk(const char type[4], const unsigned char* data, std::size_t size);
  void compress(const unsigned char* data, std::size_t size, int flush);

  io::Atomic_file file_;
  int width_, height_, rows_ = 0;
  z_stream zlib_{};
  std::vector<unsigned char> previous_row_, filtered_, compressed_;
};

}  // namespace sculpt::render
