// SPDX-License-Identifier: GPL-3.0-or-later
#include "animation.hpp"

#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>

#include "gif_animation.hpp"
#include "io/atomic_file.hpp"
#include "io/point_reader.hpp"

namespace sculpt::render {

std::optional<Animation_format> animation_format_of(const std::string& path) {
  const std::string extension = io::extension_of(path);  // lower case
  if (extension == ".webp") return Animation_format::webp;
  if (extension == ".gif") return Animation_format::gif;
  return std::nullopt;
}

Animation_writer::Animation_writer(int width, int height, int milliseconds, Animation_format format)
    : width_(width), height_(height), milliseconds_(milliseconds) {
  if (milliseconds <= 0)
    throw std::runtime_error("each picture of an animation shows for 1 ms or more");
  if (format == Animation_format::gif) {
    gif_ = std::make_unique<Gif_animation>(width, height);
    return;
  }
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options))
    throw std::runtime_error("the WebP library does not match its headers");
  options.anim_params.loop_count = 0;  // forever
  encoder_ = WebPAnimEncoderNew(width, height, &options);
  if (!encoder_) throw std::runtime_error("cannot start a WebP encoder");
}

Animation_writer::~Animation_writer() {
  if (encoder_) WebPAnimEncoderDelete(encoder_);
}

void Animation_writer::add(const Image& frame) {
  if (frame.width != width_ || frame.height != height_)
    throw std::runtime_error("the frames of an animation must be of one size");
  if (timestamp_ > std::numeric_limits<int>::max() - 4LL * milliseconds_)
    throw std::runtime_error("an animation cannot last that long");
  if (gif_) {
    // A frame's delay is written with it, and the last one's is longer: each frame waits for the
    // next before it is encoded.
    if (held_) gif_->add(*held_, centiseconds(1));
    held_ = frame;
  } else {
    add_webp(frame);
  }
  ++frames_;
  last_start_ = timestamp_;
  timestamp_ += milliseconds_;
}

int Animation_writer::centiseconds(int intervals) const {
  return std::max(2, int((intervals * (long long)milliseconds_ + 5) / 10));
}

void Animation_writer::add_webp(const Image& frame) {
  WebPConfig config;
  if (!WebPConfigInit(&config)) throw std::runtime_error("cannot start a WebP encoder");
  config.lossless = 1;
  config.quality = 50;  // lossless: effort, not loss
  config.method = 2;
  WebPPicture picture;
  if (!WebPPictureInit(&picture)) throw std::runtime_error("cannot make a WebP picture");
  picture.use_argb = 1;
  picture.width = width_;
  picture.height = height_;
  std::unique_ptr<WebPPicture, void (*)(WebPPicture*)> owned(&picture, WebPPictureFree);
  if (!WebPPictureImportRGBA(&picture, frame.rgba.data(), 4 * width_) ||
      !WebPAnimEncoderAdd(encoder_, &picture, int(timestamp_), &config)) {
    throw std::runtime_error("WebP encoding failed at frame " + std::to_string(frames_ + 1));
  }
}

std::vector<unsigned char> Animation_writer::finish_webp() {
  WebPData data;
  WebPDataInit(&data);
  // Freed on every path, a failed assembly's part included.
  std::unique_ptr<WebPData, void (*)(WebPData*)> bytes(&data, WebPDataClear);
  // The last picture is held three times as long: the end comes 3 intervals after it starts.
  const long long end = last_start_ + 3LL * milliseconds_;
  if (!WebPAnimEncoderAdd(encoder_, nullptr, int(end), nullptr) ||
      !WebPAnimEncoderAssemble(encoder_, &data)) {
    throw std::runtime_error("WebP encoding failed: " +
                             std::string(WebPAnimEncoderGetError(encoder_)));
  }
  return {data.bytes, data.bytes + data.size};
}

void Animation_writer::write(const std::string& path) {
  if (frames_ == 0) throw std::runtime_error("an animation needs at least one frame");
  std::vector<unsigned char> bytes;
  if (gif_) {
    gif_->add(*held_, centiseconds(3));  // the last picture held three times as long
    held_.reset();
    bytes = gif_->finish();
  } else {
    bytes = finish_webp();
  }
  io::Atomic_file file(path, true);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  file.commit();
}

void write_animation(const std::string& path, const std::vector<Image>& frames, int milliseconds) {
  if (frames.empty()) throw std::runtime_error("an animation needs at least one frame");
  const auto format = animation_format_of(path);
  if (!format) throw std::runtime_error("an animation is a .webp or a .gif: '" + path + "'");
  Animation_writer writer(frames.front().width, frames.front().height, milliseconds, *format);
  for (const Image& frame : frames) writer.add(frame);
  writer.write(path);
}

}  // namespace sculpt::render
