// SPDX-License-Identifier: GPL-3.0-or-later
// What both scene builders (scene_builder.cpp, section.cpp) share: adding a layer, and the
// labels the poles have at the stage shown.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sculpt::scene {

// A point of the samples as the renderer takes it (a 2D point in the plane z = 0).
template <std::size_t N>
Vec3 vec(const std::array<double, N>& p) {
  return {float(p[0]), float(p[1]), N == 3 ? float(p[N - 1]) : 0.0f};
}

// A deque: references to its layers stay valid as more are added.
inline Layer& add_layer(std::deque<Layer>& layers, const char* id, const std::string& label,
                        Primitive primitive, Color color, float size) {
  Layer layer;
  layer.id = id;
  layer.label = label;
  layer.primitive = primitive;
  layer.color = color;
  layer.size = size;
  layers.push_back(std::move(layer));
  return layers.back();
}

// During the labelling replay, the labels given so far; else the final ones. Empty for a method
// that labels none.
template <int D>
std::vector<Label> labels_at_stage(const Reconstruction<D>& r, const Request& request) {
  if (r.propagation.labels.empty()) return {};
  if (request.stage != Stage::propagation || request.step < 0) return r.propagation.labels;
  const auto& events = r.propagation.events;
  std::vector<Label> labels(r.poles.poles.size(), Label::unlabelled);
  const std::size_t shown = std::min<std::size_t>(request.step, events.size());
  for (std::size_t i = 0; i < shown; ++i) labels[events[i].pole] = events[i].label;
  return labels;
}

}  // namespace sculpt::scene
