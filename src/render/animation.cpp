// SPDX-License-Identifier: GPL-3.0-or-later
#include "animation.hpp"

#include <webp/encode.h>
#include <webp/mux.h>

#include <limits>
#include <memory>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace sculpt::render {

void write_animation(const std::string& path, const std::vector<Image>& frames, int milliseconds) {
  if (frames.empty()) throw std::runtime_error("an animation needs at least one frame");
  if (milliseconds <= 0)
    throw std::runtime_error("each picture of an animation shows for 1 ms or more");
  const int width = frames.front().width, height = frames.front().height;
  WebPAnimEncoderOptions encoder_options;
  if (!WebPAnimEncoderOptionsInit(&encoder_options))
    throw std::runtime_error("the WebP library does not match its headers");
  encoder_options.anim_params.loop_count = 0;  // forever
  std::unique_ptr<WebPAnimEncoder, void (*)(WebPAnimEncoder*)> encoder(
      WebPAnimEncoderNew(width, height, &encoder_options), WebPAnimEncoderDelete);
  WebPConfig config;
  if (!encoder || !WebPConfigInit(&config)) throw std::runtime_error("cannot start a WebP encoder");
  config.lossless = 1;
  config.quality = 50;  // lossless: effort, not loss
  config.method = 2;

  long long timestamp = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Image& frame = frames[i];
    if (frame.width != width || frame.height != height)
      throw std::runtime_error("the frames of an animation must be of one size");
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("cannot make a WebP picture");
    picture.use_argb = 1;
    picture.width = width;
    picture.height = height;
    std::unique_ptr<WebPPicture, void (*)(WebPPicture*)> owned(&picture, WebPPictureFree);
    if (timestamp > std::numeric_limits<int>::max() - 4LL * milliseconds)
      throw std::runtime_error("an animation cannot last that long");
    if (!WebPPictureImportRGBA(&picture, frame.rgba.data(), 4 * width) ||
        !WebPAnimEncoderAdd(encoder.get(), &picture, int(timestamp), &config)) {
      throw std::runtime_error("WebP encoding failed at frame " + std::to_string(i + 1));
    }
    timestamp += i + 1 == frames.size() ? 3 * milliseconds : milliseconds;
  }
  WebPData data;
  WebPDataInit(&data);
  // Freed on every path, a failed assembly's part included.
  std::unique_ptr<WebPData, void (*)(WebPData*)> bytes(&data, WebPDataClear);
  if (!WebPAnimEncoderAdd(encoder.get(), nullptr, int(timestamp), nullptr) ||
      !WebPAnimEncoderAssemble(encoder.get(), &data)) {
    throw std::runtime_error("WebP encoding failed: " +
                             std::string(WebPAnimEncoderGetError(encoder.get())));
  }
  io::Atomic_file file(path, true);
  file.stream().write(reinterpret_cast<const char*>(data.bytes), std::streamsize(data.size));
  file.commit();
}

}  // namespace sculpt::render
