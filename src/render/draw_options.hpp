// SPDX-License-Identifier: GPL-3.0-or-later
// How a scene is drawn into a picture: what beside the data (legend, title), which layers, where
// in the framebuffer and at what picture scale. Read by the renderer and by the legend's layout.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

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

inline bool hidden(const scene::Layer& layer, const Draw_options& options) {
  return std::find(options.hidden_layers.begin(), options.hidden_layers.end(), layer.id) !=
         options.hidden_layers.end();
}

}  // namespace sculpt::render
