// SPDX-License-Identifier: GPL-3.0-or-later
// Animations: frames written as an animated WebP decode back to the same pictures, in order,
// with their timing; bad frames are one clear error and no file.
#include "render/animation.hpp"

#include <gtest/gtest.h>
#include <webp/demux.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "file_support.hpp"

namespace sculpt {
namespace {

render::Image gradient(int width, int height, int shift) {
  render::Image image{width, height, std::vector<std::uint8_t>(4 * width * height)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.rgba[4 * (y * width + x)];
      p[0] = std::uint8_t(x * 7 + shift), p[1] = std::uint8_t(y * 5),
      p[2] = std::uint8_t(shift * 40);
      p[3] = 255;
    }
  }
  return image;
}

TEST(Animation, FramesComeBackLosslesslyInOrderWithTheirTiming) {
  std::vector<render::Image> frames;
  for (int k = 0; k < 5; ++k) frames.push_back(gradient(48, 32, k));
  const std::string path = testing::output_path("frames.webp");
  render::write_animation(path, frames, 100);

  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  ASSERT_NE(decoder, nullptr);
  WebPAnimInfo info;
  ASSERT_TRUE(WebPAnimDecoderGetInfo(decoder, &info));
  EXPECT_EQ(info.canvas_width, 48u);
  EXPECT_EQ(info.canvas_height, 32u);
  EXPECT_EQ(info.frame_count, 5u);
  EXPECT_EQ(info.loop_count, 0u);  // forever
  std::size_t k = 0;
  int previous = 0;
  while (WebPAnimDecoderHasMoreFrames(decoder)) {
    std::uint8_t* pixels = nullptr;
    int timestamp = 0;
    ASSERT_TRUE(WebPAnimDecoderGetNext(decoder, &pixels, &timestamp));
    ASSERT_LT(k, frames.size());
    EXPECT_TRUE(std::equal(frames[k].rgba.begin(), frames[k].rgba.end(), pixels)) << "frame " << k;
    // Each shown 100 ms; the last, held on the result, 300.
    EXPECT_EQ(timestamp - previous, k + 1 == frames.size() ? 300 : 100) << "frame " << k;
    previous = timestamp;
    ++k;
  }
  EXPECT_EQ(k, frames.size());
  WebPAnimDecoderDelete(decoder);
}

TEST(Animation, FramesOfDifferentSizesAreOneErrorAndNoFile) {
  const std::string path = testing::output_path("mixed.webp");
  EXPECT_THROW(render::write_animation(path, {gradient(8, 8, 0), gradient(9, 8, 1)}, 50),
               std::runtime_error);
  EXPECT_THROW(render::write_animation(path, {}, 50), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sculpt
