// SPDX-License-Identifier: GPL-3.0-or-later
#include "image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace sculpt::render {

void write_png(const std::string& path, const Image& image) {
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4)) {
    throw std::runtime_error("cannot encode a PNG for '" + path + "'");
  }
  io::Atomic_file file(path, true);
  file.stream().write(png.data(), static_cast<std::streamsize>(png.size()));
  file.commit();
}

Image read_png(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
  if (!data) throw std::runtime_error("cannot read the PNG '" + path + "'");
  image.rgba.assign(data, data + std::size_t(image.width) * image.height * 4);
  stbi_image_free(data);
  return image;
}

Comparison compare(const Image& expected, const Image& actual, int tolerance) {
  Comparison result;
  if (expected.width != actual.width || expected.height != actual.height) return result;
  result.difference = expected;
  result.largest_difference = 0;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < expected.rgba.size(); i += 4) {
    int difference = 0;
    for (int c = 0; c < 4; ++c) {
      difference =
          std::max(difference, std::abs(int(expected.rgba[i + c]) - int(actual.rgba[i + c])));
    }
    result.largest_difference = std::max(result.largest_difference, difference);
    std::uint8_t* out = &result.difference.rgba[i];
    if (difference > tolerance) {
      ++mismatches;
      out[0] = 255, out[1] = 0, out[2] = 0, out[3] = 255;
    } else {
      for (int c = 0; c < 3; ++c) out[c] = std::uint8_t(255 - (255 - out[c]) / 4);
    }
  }
  result.mismatch_ratio = double(mismatches) / (expected.rgba.size() / 4);
  return result;
}

std::size_t count_pixels_near(const Image& image, float r, float g, float b, int tolerance) {
  const int target[3] = {int(std::lround(r * 255)), int(std::lround(g * 255)),
                         int(std::lround(b * 255))};
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    bool near = true;
    for (int c = 0; c < 3 && near; ++c)
      near = std::abs(int(image.rgba[i + c]) - target[c]) <= tolerance;
    count += near;
  }
  return count;
}

}  // namespace sculpt::render
