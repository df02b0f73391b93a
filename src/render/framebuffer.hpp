// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures drawn offscreen in the GL context current on this thread: into a 4x multisampled
// framebuffer object, resolved and read back, whatever the window shows. OpenGL 3.3 and WebGL 2
// both have what this needs.
#pragma once

#include <memory>

#include "render/picture_renderer.hpp"

namespace sculpt::render {

// Draws `scene` with `renderer` (made in the current context) into an offscreen framebuffer of
// width x height and reads it back; the scene stays uploaded to `renderer`. Throws
// std::runtime_error for a size out of range or a framebuffer the context cannot make.
Image draw_offscreen(Renderer& renderer, const scene::Scene& scene, const Camera& camera, int width,
                     int height, const Draw_options& options);

// Pictures in the context that is current when it is made (the viewer's window), through a
// renderer of its own, so the scene on screen stays as it is.
class Context_picture_renderer : public Picture_renderer {
 public:
  Context_picture_renderer();
  ~Context_picture_renderer() override;
  Image render(const scene::Scene& scene, const Camera& camera, int width, int height,
               const Draw_options& options = {}) override;

 private:
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace sculpt::render
