// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's picture of the scene, kept in an offscreen framebuffer and drawn again only when
// what it shows changes: the scene, the camera, the layers shown, the size. Every other frame
// (the panel's progress bar while a reconstruction runs, the mouse over a menu) copies it to
// the window, which costs next to nothing where drawing the scene does not: software renderers
// (SwiftShader in a browser without a GPU, llvmpipe) draw thousands of balls and edges with 4x
// multisampling slowly. The window's own framebuffer needs no multisampling: the picture has it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/renderer.hpp"

namespace sculpt::render {

class Picture_cache {
 public:
  Picture_cache() = default;
  ~Picture_cache();
  Picture_cache(const Picture_cache&) = delete;
  Picture_cache& operator=(const Picture_cache&) = delete;

  // Draws the renderer's scene as Renderer::draw would, into the framebuffer bound when called
  // (at options.viewport_x, viewport_y): from the cache if nothing it shows has changed.
  void draw(Renderer& renderer, const Camera& camera, int width, int height,
            const Draw_options& options);
  // How many times the scene was drawn (the tests see the cache work).
  std::uint64_t scenes_drawn() const { return scenes_drawn_; }

 private:
  struct Key {
    std::uint64_t scene = 0;
    Camera camera;
    int width = 0, height = 0;
    bool legend = false, title = false;
    scene::Color background;
    std::vector<std::string> hidden_layers;
    float picture_scale = 1;
  };
  static bool same(const Key& a, const Key& b);
  void make_framebuffers(int width, int height);
  void release();

  std::optional<Key> cached_;
  unsigned multisampled_ = 0, resolved_ = 0;  // framebuffers
  unsigned renderbuffers_[3] = {0, 0, 0};     // multisampled colour and depth, resolved colour
  int width_ = 0, height_ = 0;
  std::uint64_t scenes_drawn_ = 0;
};

}  // namespace sculpt::render
