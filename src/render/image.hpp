// SPDX-License-Identifier: GPL-3.0-or-later
// An RGBA picture in memory: written and read as PNG (stb), and compared with a golden image by
// a per-pixel tolerance and the share of pixels beyond it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sculpt::render {

// The largest side of a picture: 4x multisampled colour and depth of 8192^2 take 2 GiB already.
inline constexpr int max_image_side = 8192;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows from the top

  const std::uint8_t* pixel(int x, int y) const { return &rgba[4 * (std::size_t(y) * width + x)]; }
};

void write_png(const std::string& path, const Image& image);  // throws std::runtime_error
Image read_png(const std::string& path);                      // throws std::runtime_error

struct Comparison {
  double mismatch_ratio = 1.0;  // share of pixels whose channels differ by more than the tolerance
  int largest_difference = 255;
  Image difference;  // mismatching pixels in red over a faded copy of the expected
};

Comparison compare(const Image& expected, const Image& actual, int tolerance);

// Pixels whose colour is within `tolerance` of (r, g, b) on every channel.
std::size_t count_pixels_near(const Image& image, float r, float g, float b, int tolerance);

}  // namespace sculpt::render
