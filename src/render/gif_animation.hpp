// SPDX-License-Identifier: GPL-3.0-or-later
// An animated GIF (giflib), what slide software plays where it plays no WebP. Each frame gets
// its own 256 colours (exactly its own when it has no more; else giflib's median cut, close
// for the flat colours and smooth shading of these pictures) and a delay in hundredths of a
// second; the animation loops forever. Frames are encoded as they come, into memory; the whole
// file is handed back at the end.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"

struct GifFileType;

namespace sculpt::render {

class Gif_animation {
 public:
  Gif_animation(int width, int height);  // throws std::runtime_error
  ~Gif_animation();
  Gif_animation(const Gif_animation&) = delete;
  Gif_animation& operator=(const Gif_animation&) = delete;

  // A frame of the animation's size, shown `centiseconds`.
  void add(const Image& frame, int centiseconds);
  // The file's bytes; nothing may be added after.
  std::vector<unsigned char> finish();

 private:
  [[noreturn]] void fail(const std::string& what) const;

  int width_, height_;
  GifFileType* gif_ = nullptr;
  std::vector<unsigned char> bytes_;
};

}  // namespace sculpt::render
