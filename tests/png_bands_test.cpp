// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures written a band at a time (render/png_band_writer.hpp): the same pixels as the picture
// written whole, in a PNG any reader decodes, and compare's grid composed a row of tiles at a
// time, one row per input.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "file_support.hpp"
#include "io/io_error.hpp"
#include "render/png_band_writer.hpp"

namespace sculpt {
namespace {

// A picture with what the PNG filters are for: flat areas, gradients, edges and noise.
render::Image test_picture(int width, int height) {
  render::Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(4 * std::size_t(width) * height);
  unsigned state = 12345;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.rgba[4 * (std::size_t(y) * width + x)];
      state = state * 1103515245u + 12345u;
      p[0] = static_cast<std::uint8_t>(x * 255 / width);
      p[1] = static_cast<std::uint8_t>(y < height / 2 ? 40 : y * 3);
      p[2] = static_cast<std::uint8_t>((x / 7 + y / 5) % 2 ? 200 : state >> 24);
      p[3] = static_cast<std::uint8_t>(x < width / 3 ? 255 : 128 + (state >> 25));
    }
  }
  return image;
}

render::Image rows_of(const render::Image& image, int top, int count) {
  render::Image band;
  band.width = image.width;
  band.height = count;
  band.rgba.assign(image.rgba.begin() + 4 * std::size_t(top) * image.width,
                   image.rgba.begin() + 4 * std::size_t(top + count) * image.width);
  return band;
}

// Every chunk's CRC, and the IDAT chunks' zlib stream with its checksum, checked as a strict
// decoder would (stb's skips both); returns the inflated scanlines' size.
std::size_t check_chunks(const std::string& png) {
  EXPECT_EQ(png.compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);
  std::string compressed;
  std::size_t at = 8;
  bool ended = false;
  const auto big_endian = [&](std::size_t from) {
    std::uint32_t value = 0;
    for (int k = 0; k < 4; ++k) value = value << 8 | static_cast<unsigned char>(png[from + k]);
    return value;
  };
  while (at + 12 <= png.size()) {
    const std::uint32_t length = big_endian(at);
    const std::string type = png.substr(at + 4, 4);
    const auto* bytes = reinterpret_cast<const Bytef*>(png.data() + at + 4);
    EXPECT_EQ(crc32(0, bytes, 4 + length), big_endian(at + 8 + length)) << type << " at " << at;
    if (type == "IDAT") compressed += png.substr(at + 8, length);
    ended = type == "IEND";
    at += 12 + length;
  }
  EXPECT_TRUE(ended);
  EXPECT_EQ(at, png.size());
  std::vector<Bytef> scanlines(64 << 20);
  uLongf size = scanlines.size();
  EXPECT_EQ(uncompress(scanlines.data(), &size, reinterpret_cast<const Bytef*>(compressed.data()),
                       compressed.size()),
            Z_OK);
  return size;
}

TEST(Png_bands, GiveThePicturePixelForPixel) {
  const render::Image picture = test_picture(173, 91);
  const std::string path = testing::output_path("bands.png");
  render::Png_band_writer writer(path, picture.width, picture.height);
  for (const auto& [top, count] : {std::pair{0, 1}, {1, 40}, {41, 50}}) {
    writer.add(rows_of(picture, top, count));
  }
  EXPECT_FALSE(std::filesystem::exists(path)) << "nothing under the name before the end";
  writer.finish();
  const render::Image read = render::read_png(path);  // stb's decoder, not ours
  ASSERT_EQ(read.width, picture.width);
  ASSERT_EQ(read.height, picture.height);
  EXPECT_EQ(read.rgba, picture.rgba);
  // Filtered and compressed: far smaller than the raw pixels for the flat and smooth parts.
  EXPECT_LT(std::filesystem::file_size(path), picture.rgba.size());
  // A filter byte and the pixels per row, every checksum right.
  EXPECT_EQ(check_chunks(testing::read_file(path)), std::size_t(91) * (1 + 4 * 173));
}

TEST(Png_bands, AnUnfinishedPictureLeavesNoFile) {
  const std::string path = testing::output_path("unfinished.png");
  {
    render::Png_band_writer writer(path, 20, 10);
    writer.add(rows_of(test_picture(20, 10), 0, 5));
    EXPECT_THROW(writer.finish(), std::logic_error);  // five rows are missing
    EXPECT_THROW(writer.add(test_picture(21, 5)), std::logic_error);
  }
  const auto folder = std::filesystem::path(path).parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    EXPECT_EQ(entry.path().filename().string().find("unfinished"), std::string::npos)
        << entry.path();
  }
}

// The grid of `sculpt compare`: a row of tiles per input, a tile per method.
TEST(Png_bands, CompareDrawsARowPerInput) {
  const std::string grid = testing::output_path("compare-grid.png");
  const std::string command = std::string(SCULPT_EXECUTABLE) +
                              " compare --example star --example bumpy --methods robust,crust "
                              "--tile 64x48 --pictures " +
                              grid + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const render::Image read = render::read_png(grid);
  ASSERT_EQ(read.width, 2 * 64);
  ASSERT_EQ(read.height, 2 * 48);
  EXPECT_EQ(check_chunks(testing::read_file(grid)), std::size_t(96) * (1 + 4 * 128));
  // Every tile holds a drawing: pixels of more than one colour.
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 2; ++column) {
      const std::uint8_t* corner = read.pixel(64 * column, 48 * row);
      bool varied = false;
      for (int y = 48 * row; y < 48 * (row + 1) && !varied; ++y) {
        for (int x = 64 * column; x < 64 * (column + 1) && !varied; ++x) {
          varied = !std::equal(corner, corner + 3, read.pixel(x, y));
        }
      }
      EXPECT_TRUE(varied) << "tile " << row << ", " << column;
    }
  }
}

}  // namespace
}  // namespace sculpt
