// SPDX-License-Identifier: GPL-3.0-or-later
// An animation of pictures (the replay of the labelling, a sweep through the stages) as an
// animated WebP (libwebpmux), which browsers and image viewers play, or an animated GIF
// (gif_animation.hpp), which slide software plays too. Frames are encoded as they come: a long
// animation holds its compressed frames, never every picture.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image.hpp"

struct WebPAnimEncoder;

namespace sculpt::render {

class Gif_animation;

enum class Animation_format { webp, gif };

// The format a path's extension names (.webp or .gif, in any case), or nothing.
std::optional<Animation_format> animation_format_of(const std::string& path);

// Frames of one size, each shown `milliseconds` (the last one held three times as long, so a
// loop pauses on the result); WebP losslessly (thin lines stay sharp), GIF in 256 colours a frame
// and hundredths of a second (at least 2: browsers slow down shorter delays). Errors are
// std::runtime_error with a one-line message.
class Animation_writer {
 public:
  Animation_writer(int width, int height, int milliseconds,
                   Animation_format format = Animation_format::webp);
  ~Animation_writer();
  Animation_writer(const Animation_writer&) = delete;
  Animation_writer& operator=(const Animation_writer&) = delete;

  void add(const Image& frame);  // encoded now; the picture may be dropped
  // Writes the animation to `path`, all or nothing.
  void write(const std::string& path);

 private:
  void add_webp(const Image& frame);
  int centiseconds(int intervals) const;  // a GIF delay: this many frame intervals
  std::vector<unsigned char> finish_webp();

  int width_, height_, milliseconds_;
  WebPAnimEncoder* encoder_ = nullptr;  // one of the two, as the format asked
  std::unique_ptr<Gif_animation> gif_;
  std::optional<Image> held_;  // GIF: the frame last given, written when its delay is known
  long long timestamp_ = 0, last_start_ = 0;
  int frames_ = 0;
};

// The frames at once: an Animation_writer fed them in order, in the format the path names.
void write_animation(const std::string& path, const std::vector<Image>& frames, int milliseconds);

}  // namespace sculpt::render
