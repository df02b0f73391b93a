// SPDX-License-Identifier: GPL-3.0-or-later
// The scene tests' one way to look a layer up by its id.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace sculpt::testing {

inline const scene::Layer* find_layer(const scene::Scene& scene, const std::string& id) {
  for (const auto& layer : scene.layers) {
    if (layer.id == id) return &layer;
  }
  return nullptr;
}

}  // namespace sculpt::testing
