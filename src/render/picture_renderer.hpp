// SPDX-License-Identifier: GPL-3.0-or-later
// What draws a scene into a picture in memory: the headless renderer (an OSMesa context of its
// own, for the command line, the figures and Python) or a framebuffer of the window's own context
// (the viewer's exports, on the desktop and in the browser). The shots (frontend/shots.hpp) draw
// through either.
#pragma once

#include "render/camera.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace sculpt::render {

class Picture_renderer {
 public:
  virtual ~Picture_renderer() = default;
  // A width x height picture of the scene; throws std::runtime_error with a one-line message.
  virtual Image render(const scene::Scene& scene, const Camera& camera, int width, int height,
                       const Draw_options& options = {}) = 0;
};

}  // namespace sculpt::render
