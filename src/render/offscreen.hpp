// SPDX-License-Identifier: GPL-3.0-or-later
// What the headless rendering module offers (libsculpt_osmesa.so, src/render/osmesa_offscreen.cpp):
// an OpenGL 3.3 core context of Mesa's llvmpipe through OSMesa, drawing scenes into offscreen
// images. It lives in a module loaded on first use (headless.cpp) because libOSMesa brings
// libLLVM, ~50 MiB resident and tens of milliseconds of loading, which `sculpt reconstruct`
// and the benchmark's measurements must not pay.
#pragma once

#include <string>

#include "render/image.hpp"
#include "render/renderer.hpp"

namespace sculpt::render {

class Offscreen_renderer {
 public:
  virtual ~Offscreen_renderer() = default;
  virtual Image render(const scene::Scene& scene, const Camera& camera, int width, int height,
                       const Draw_options& options) = 0;
  virtual const char* gl_renderer() const = 0;
};

// The module's one entry point: a renderer, or null with the reason in `error`. Scenes, cameras
// and images cross the boundary as C++ objects, and exceptions from render() too (both sides
// share libstdc++): a module built from other sources refuses a caller of another version.
inline constexpr int offscreen_interface_version = 1;
using Make_offscreen_renderer = Offscreen_renderer* (*)(int interface_version, std::string* error);
inline constexpr const char* make_offscreen_renderer_symbol = "sculpt_make_offscreen_renderer";
inline constexpr const char* offscreen_module_name = "libsculpt_osmesa.so";

}  // namespace sculpt::render
