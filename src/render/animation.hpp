// SPDX-License-Identifier: GPL-3.0-or-later
// An animation of pictures (the replay of the labelling, a sweep through the stages) as an
// animated WebP (libwebpmux), which browsers, slide software and image viewers play. Frames are
// encoded as they come: a long animation holds its compressed frames, never every picture.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image.hpp"

struct WebPAnimEncoder;

namespace sculpt::render {

// Frames of one size, each shown `milliseconds` (the last one held three times as long, so a
// loop pauses on the result), losslessly: thin lines stay sharp. Errors are std::runtime_error
// with a one-line message.
class Animation_writer {
 public:
  Animation_writer(int width, int height, int milliseconds);
  ~Animation_writer();
  Animation_writer(const Animation_writer&) = delete;
  Animation_writer& operator=(const Animation_writer&) = delete;

  void add(const Image& frame);  // encoded now; the picture may be dropped
  // Writes the animation to `path`, all or nothing.
  void write(const std::string& path);

 private:
  int width_, height_, milliseconds_;
  WebPAnimEncoder* encoder_;
  long long timestamp_ = 0, last_start_ = 0;
  int frames_ = 0;
};

// The frames at once: an Animation_writer fed them in order.
void write_animation(const std::string& path, const std::vector<Image>& frames, int milliseconds);

}  // namespace sculpt::render
