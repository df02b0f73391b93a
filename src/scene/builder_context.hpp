// SPDX-License-Identifier: GPL-3.0-or-later
// What the stage builder (scene_builder.cpp) and the layers it draws from its parts
// (result_layers.hpp, candidate_layers.hpp, pole_layers.hpp, cleaning_layers.hpp) work on together:
// the reconstruction, the request, the scene (its title and box) and the layers gathered so far.
// One struct, so that each part takes the builder's state as one argument and no part keeps a copy
// of its helpers.
#pragma once

#include <deque>
#include <sculpt/sculpt.hpp>
#include <stdexcept>
#include <string>

#include "layer_helpers.hpp"
#include "scene.hpp"

namespace sculpt::scene {

template <int D>
struct Builder_context {
  const Reconstruction<D>& r;
  const Request& request;
  Scene& scene;               // its title and box: its layers are filled from `layers` at the end
  std::deque<Layer>& layers;  // in the legend's order
  int n;                      // the samples: the first n sites

  Layer& add(const char* id, const std::string& label, Primitive primitive, Color color,
             float size) const {
    return add_layer(layers, id, label, primitive, color, size);
  }
};

inline constexpr const char* triangulations_not_kept =
    "this stage needs the triangulations, which the reconstruction did not keep "
    "(keep_triangulations)";

template <int D>
void require_cells(const Delaunay_stage<D>& stage) {
  if (stage.cells.size() != stage.cell_count) throw std::invalid_argument(triangulations_not_kept);
}

}  // namespace sculpt::scene
