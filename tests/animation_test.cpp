// SPDX-License-Identifier: GPL-3.0-or-later
// Animations: frames written as an animated WebP (or GIF, for pictures of at most 256 colours)
// decode back to the same pictures, in order, with their timing; bad frames are one clear error
// and no file.
#include "render/animation.hpp"

#include <gif_lib.h>
#include <gtest/gtest.h>
#include <webp/demux.h>

#include <cstdio>
#include <cstdlib>
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

// Blocks of 16 flat colours, different in each frame: a GIF keeps them exactly.
render::Image blocks(int width, int height, int shift) {
  render::Image image{width, height, std::vector<std::uint8_t>(4 * width * height)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.rgba[4 * (y * width + x)];
      p[0] = std::uint8_t(60 * (4 * x / width) + 10 * shift);
      p[1] = std::uint8_t(60 * (4 * y / height));
      p[2] = std::uint8_t(40 * shift);
      p[3] = 255;
    }
  }
  return image;
}

TEST(Animation, GifFramesComeBackInOrderWithTheirTimingAndLoop) {
  std::vector<render::Image> frames;
  for (int k = 0; k < 5; ++k) frames.push_back(blocks(48, 32, k));
  const std::string path = testing::output_path("frames.GIF");  // any case
  render::write_animation(path, frames, 100);

  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  ASSERT_NE(gif, nullptr) << GifErrorString(error);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK) << GifErrorString(gif->Error);
  EXPECT_EQ(gif->SWidth, 48);
  EXPECT_EQ(gif->SHeight, 32);
  ASSERT_EQ(gif->ImageCount, 5);
  bool loops = false;  // the NETSCAPE2.0 extension, before the first frame
  for (int e = 0; e < gif->SavedImages[0].ExtensionBlockCount; ++e) {
    const ExtensionBlock& block = gif->SavedImages[0].ExtensionBlocks[e];
    loops = loops || (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
                      std::string(reinterpret_cast<char*>(block.Bytes), 11) == "NETSCAPE2.0");
  }
  EXPECT_TRUE(loops);
  for (int k = 0; k < gif->ImageCount; ++k) {
    const SavedImage& image = gif->SavedImages[k];
    const ColorMapObject* map =
        image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
    ASSERT_NE(map, nullptr);
    std::size_t differ = 0;
    for (int i = 0; i < 48 * 32; ++i) {
      const GifColorType colour = map->Colors[image.RasterBits[i]];
      const std::uint8_t* want = &frames[k].rgba[4 * i];
      differ += colour.Red != want[0] || colour.Green != want[1] || colour.Blue != want[2];
    }
    EXPECT_EQ(differ, 0u) << "frame " << k;
    GraphicsControlBlock control;
    ASSERT_EQ(DGifSavedExtensionToGCB(gif, k, &control), GIF_OK);
    // Each shown 100 ms (10 hundredths); the last, held on the result, 300.
    EXPECT_EQ(control.DelayTime, k + 1 == 5 ? 30 : 10) << "frame " << k;
  }
  DGifCloseFile(gif, &error);
}

// A picture of more colours than a GIF frame holds (shading) comes back close: giflib's median
// cut, each pixel's channels on average within a few levels of 255.
TEST(Animation, AGifOfManyColoursComesBackClose) {
  const render::Image many = gradient(48, 32, 3);  // 1,536 colours
  const std::string path = testing::output_path("many.gif");
  render::write_animation(path, {many, many}, 50);
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  ASSERT_NE(gif, nullptr);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK);
  ASSERT_EQ(gif->ImageCount, 2);
  const SavedImage& image = gif->SavedImages[0];
  const ColorMapObject* map = image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
  double total = 0;
  int worst = 0;
  for (int i = 0; i < 48 * 32; ++i) {
    const GifColorType colour = map->Colors[image.RasterBits[i]];
    for (int c = 0; c < 3; ++c) {
      const int got = c == 0 ? colour.Red : c == 1 ? colour.Green : colour.Blue;
      const int off = std::abs(got - int(many.rgba[4 * i + c]));
      total += off;
      worst = std::max(worst, off);
    }
  }
  std::printf("GIF of 1,536 colours: mean error %.2f, worst %d (of 255)\n", total / (3 * 48 * 32),
              worst);
  EXPECT_LT(total / (3 * 48 * 32), 8.0);  // measured 5.3
  EXPECT_LE(worst, 64);                   // measured 48, on colours spread over the whole cube
  DGifCloseFile(gif, &error);
}

TEST(Animation, AnAnimationIsAWebpOrAGif) {
  EXPECT_EQ(render::animation_format_of("a.webp"), render::Animation_format::webp);
  EXPECT_EQ(render::animation_format_of("dir.gif/a.Gif"), render::Animation_format::gif);
  EXPECT_FALSE(render::animation_format_of("a.png"));
  const std::string path = testing::output_path("frames.png");
  EXPECT_THROW(render::write_animation(path, {blocks(8, 8, 0)}, 50), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(Animation, FramesOfDifferentSizesAreOneErrorAndNoFile) {
  for (const std::string name : {"mixed.webp", "mixed.gif"}) {
    const std::string path = testing::output_path(name);
    EXPECT_THROW(render::write_animation(path, {gradient(8, 8, 0), gradient(9, 8, 1)}, 50),
                 std::runtime_error);
    EXPECT_THROW(render::write_animation(path, {}, 50), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(path));
  }
}

}  // namespace
}  // namespace sculpt
