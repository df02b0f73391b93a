// SPDX-License-Identifier: GPL-3.0-or-later
// Rendering for the tests: one headless renderer for the whole test program, and scenes of
// built-in examples.
#pragma once

#include <memory>

#include "render/headless.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::testing {

inline render::Headless_renderer& headless() {
  static auto renderer = std::make_unique<render::Headless_renderer>();
  return *renderer;
}

// The goldens and layer tests show the paper's stages (DT(S + OUP) exists only there).
inline Options paper_method() {
  Options options;
  options.method = Method::paper;
  return options;
}

inline const Reconstruction<2>& star_reconstruction() {
  static const auto result = reconstruct(shapes::star(100).samples, paper_method());
  return result;
}

inline const Reconstruction<3>& bumpy_reconstruction() {
  static const auto result = reconstruct(shapes::bumpy_sphere(1500), paper_method());
  return result;
}

inline render::Image render_scene(const scene::Scene& scene, int size, bool legend = false) {
  render::Draw_options options;
  options.legend = options.title = legend;
  return headless().render(scene, render::fit(scene), size, size, options);
}

inline std::size_t non_background_pixels(const render::Image& image) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    count += image.rgba[i] < 250 || image.rgba[i + 1] < 250 || image.rgba[i + 2] < 250;
  }
  return count;
}

}  // namespace sculpt::testing
