// SPDX-License-Identifier: GPL-3.0-or-later
// Draws a scene with OpenGL 3.3 core into whatever framebuffer is bound: the viewer's window or
// the headless renderer's offscreen buffer. Knows nothing of windows or contexts; it needs only
// a current GL 3.3 context when constructed and used.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/camera.hpp"
#include "render/draw_options.hpp"
#include "render/image.hpp"
#include "render/legend_layout.hpp"
#include "scene/scene.hpp"

namespace sculpt::render {

// Reads the bound framebuffer's colour into an image (rows from the top).
Image read_pixels(int width, int height);

class Renderer {
 public:
  Renderer();  // compiles the programs: throws std::runtime_error with the GL log on failure
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads a scene's layers to the GPU; they stay there until the next call.
  void set_scene(const scene::Scene& scene);
  // Draws the uploaded scene into a width x height viewport of the bound framebuffer.
  void draw(const Camera& camera, int width, int height, const Draw_options& options = {});
  // The uploaded scene without its geometry: its layers' ids, labels and colours.
  const scene::Scene& scene() const { return legend_.scene(); }
  // Where the uploaded scene's legend goes: the viewer's fit steps back by it.
  const Legend_layout& legend() const { return legend_; }
  // Counts the scenes uploaded: a picture of the scene is stale when this has changed.
  std::uint64_t scene_generation() const { return generation_; }

 private:
  struct Programs;
  struct Gpu_layer;
  std::unique_ptr<Programs> programs_;
  std::vector<Gpu_layer> layers_;
  Legend_layout legend_;  // the scene without its geometry, and where its data lies
  std::uint64_t generation_ = 0;
  unsigned overlay_array_ = 0, overlay_buffer_ = 0;

  void draw_layer(const Gpu_layer& layer, const scene::Layer& info, const Camera& camera, int width,
                  int height, float picture_scale);
  void draw_overlay(const Camera& camera, int width, int height, const Draw_options& options);
};

}  // namespace sculpt::render
