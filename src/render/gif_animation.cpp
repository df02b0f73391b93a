// SPDX-License-Identifier: GPL-3.0-or-later
#include "gif_animation.hpp"

#include <gif_lib.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace sculpt::render {
namespace {

// giflib's output function: the bytes are kept in memory (GifFileType::UserData).
int append_bytes(GifFileType* gif, const GifByteType* bytes, int count) {
  auto* out = static_cast<std::vector<unsigned char>*>(gif->UserData);
  out->insert(out->end(), bytes, bytes + count);
  return count;
}

// A picture of at most 256 colours (flat 2D drawings) keeps them exactly: its own palette, in
// the order the colours first appear. False, with nothing promised, when there are more.
bool index_exactly(const Image& frame, std::vector<GifByteType>& indices, GifColorType* palette) {
  std::unordered_map<std::uint32_t, GifByteType> index_of;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const std::uint8_t* p = &frame.rgba[4 * i];
    const std::uint32_t colour = std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
    auto found = index_of.find(colour);
    if (found == index_of.end()) {
      if (index_of.size() == 256) return false;
      const auto index = GifByteType(index_of.size());
      palette[index] = GifColorType{p[0], p[1], p[2]};
      found = index_of.emplace(colour, index).first;
    }
    indices[i] = found->second;
  }
  return true;
}

}  // namespace

Gif_animation::Gif_animation(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw std::runtime_error("a GIF is 1 to 65535 pixels wide and high");
  int error = 0;
  gif_ = EGifOpen(&bytes_, append_bytes, &error);
  if (!gif_) throw std::runtime_error(std::string("cannot start a GIF: ") + GifErrorString(error));
  EGifSetGifVersion(gif_, true);  // GIF89a: delays and looping
  if (EGifPutScreenDesc(gif_, width, height, 8, 0, nullptr) == GIF_ERROR) fail("its screen");
  // Loop forever: the NETSCAPE2.0 application extension, a loop count of 0.
  const GifByteType application[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  const GifByteType loop_forever[] = {1, 0, 0};
  if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, sizeof application, application) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, sizeof loop_forever, loop_forever) == GIF_ERROR ||
      EGifPutExtensionTrailer(gif_) == GIF_ERROR) {
    fail("its looping");
  }
}

Gif_animation::~Gif_animation() {
  if (gif_) EGifCloseFile(gif_, nullptr);
}

void Gif_animation::fail(const std::string& what) const {
  throw std::runtime_error("GIF encoding failed at " + what + ": " +
                           GifErrorString(gif_ ? gif_->Error : 0));
}

void Gif_animation::add(const Image& frame, int centiseconds) {
  if (!gif_) throw std::runtime_error("a finished GIF takes no more frames");
  if (frame.width != width_ || frame.height != height_)
    throw std::runtime_error("the frames of an animation must be of one size");
  const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
  std::vector<GifByteType> indices(pixels);
  GifColorType palette[256] = {};
  if (!index_exactly(frame, indices, palette)) {
    // More than 256 colours (shading, smoothed edges): giflib's median cut, which keeps 5 bits a
    // channel (an error of at most 7 in 255).
    std::vector<GifByteType> red(pixels), green(pixels), blue(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
      red[i] = frame.rgba[4 * i];
      green[i] = frame.rgba[4 * i + 1];
      blue[i] = frame.rgba[4 * i + 2];
    }
    int colours = 256;
    if (GifQuantizeBuffer(unsigned(width_), unsigned(height_), &colours, red.data(), green.data(),
                          blue.data(), indices.data(), palette) == GIF_ERROR) {
      fail("reducing a frame to 256 colours");
    }
  }
  // A colour map's size is a power of two: all 256 entries (those past `colours` unused).
  std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(GifMakeMapObject(256, palette),
                                                                 GifFreeMapObject);
  if (!map) throw std::runtime_error("GIF encoding failed: out of memory");

  GraphicsControlBlock control;
  control.DisposalMode = DISPOSE_DO_NOT;
  control.UserInputFlag = false;
  control.DelayTime = centiseconds;
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const std::size_t length = EGifGCBToExtension(&control, extension);
  if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, int(length), extension) == GIF_ERROR ||
      EGifPutImageDesc(gif_, 0, 0, width_, height_, false, map.get()) == GIF_ERROR) {
    fail("a frame's header");
  }
  for (int row = 0; row < height_; ++row) {
    if (EGifPutLine(gif_, indices.data() + std::size_t(row) * std::size_t(width_), width_) ==
        GIF_ERROR) {
      fail("a frame's pixels");
    }
  }
}

std::vector<unsigned char> Gif_animation::finish() {
  if (!gif_) throw std::runtime_error("a GIF is finished once");
  int error = 0;
  const int closed = EGifCloseFile(gif_, &error);  // writes the trailer, frees the encoder
  gif_ = nullptr;
  if (closed == GIF_ERROR)
    throw std::runtime_error(std::string("GIF encoding failed at its end: ") +
                             GifErrorString(error));
  return std::move(bytes_);
}

}  // namespace sculpt::render
