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
#include "render/image.hpp"
#include "scene/scene.hpp"

namespace sculpt::render {

struct Draw_options {
  bool legend = true;  // colour swatches with the layers' labels, in the corner clearest of data
  bool title = true;   // the stage's title, bottom left
  scene::Color background{1, 1, 1, 1};
  std::vector<std::string> hidden_layers;  // layer ids not to draw (nor list in the legend)
  int viewport_x = 0;       // left edge of the drawing area in the framebuffer (the viewer's panel)
  int viewport_y = 0;       // its bottom edge (the viewer's figure caption below the picture)
  float picture_scale = 1;  // points and lines this many times their size (a projector: 2)
};

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
  const scene::Scene& scene() const { return scene_; }
  // Whether the legend (Draw_options::legend) would lie over drawn data in a width x height
  // picture seen by `camera`, wherever it goes: the viewer's fit zooms out until it does not.
  bool legend_over_data(const Camera& camera, int width, int height,
                        const Draw_options& options) const;
  // Counts the scenes uploaded: a picture of the scene is stale when this has changed.
  std::uint64_t scene_generation() const { return generation_; }

 private:
  struct Programs;
  struct Gpu_layer;
  std::unique_ptr<Programs> programs_;
  std::vector<Gpu_layer> layers_;
  std::vector<std::vector<glm::vec4>> landmarks_;  // per layer: where it lies (set_scene)
  scene::Scene scene_;  // the scene without its geometry: kinds, colours, labels
  std::uint64_t generation_ = 0;
  unsigned overlay_array_ = 0, overlay_buffer_ = 0;

  void draw_layer(const Gpu_layer& layer, const scene::Layer& info, const Camera& camera, int width,
                  int height, float picture_scale);
  void draw_overlay(const Camera& camera, int width, int height, const Draw_options& options);
  struct Corner {
    float x = 0, y = 0;       // the legend box's top left, in pixels from the top left
    std::size_t covered = 0;  // the data's landmarks under it
  };
  struct Legend_place {
    std::vector<const scene::Layer*> listed;
    float size = 1, pad = 0, w = 0, h = 0;  // text scale; the box inside its border
    Corner corner;
  };
  Corner emptiest_corner(const Camera& camera, int width, int height, float w, float h, float inset,
                         float title_width, float title_height, const Draw_options& options) const;
  Legend_place place_legend(const Camera& camera, int width, int height,
                            const Draw_options& options) const;
  std::vector<std::string> title_lines(int width, int height, const Draw_options& options) const;
  static float text_scale(int height, const Draw_options& options);
  static bool hidden(const scene::Layer& layer, const Draw_options& options);
};

}  // namespace sculpt::render
