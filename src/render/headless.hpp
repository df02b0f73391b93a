// SPDX-License-Identifier: GPL-3.0-or-later
// Rendering without a display: an OSMesa OpenGL 3.3 core context (Mesa's llvmpipe) drawing into
// a 4x multisampled offscreen framebuffer, read back as an Image. The renderer is the viewer's.
// The GL side lives in a module (offscreen.hpp) loaded by the first Headless_renderer, so that a
// program that never renders never loads libOSMesa.
#pragma once

#include <memory>

#include "render/picture_renderer.hpp"

namespace sculpt::render {

class Headless_renderer : public Picture_renderer {
 public:
  // Throws std::runtime_error if the module cannot be loaded or no GL 3.3 context can be made.
  Headless_renderer();
  ~Headless_renderer() override;
  Headless_renderer(const Headless_renderer&) = delete;
  Headless_renderer& operator=(const Headless_renderer&) = delete;

  Image render(const scene::Scene& scene, const Camera& camera, int width, int height,
               const Draw_options& options = {}) override;

  const char* gl_renderer() const;  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  std::unique_ptr<class Offscreen_renderer> offscreen_;
};

}  // namespace sculpt::render
