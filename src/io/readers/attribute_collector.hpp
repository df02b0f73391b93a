// SPDX-License-Identifier: GPL-3.0-or-later
// Normals and colours as a reader meets them, vertex by vertex. A file gives an attribute for
// every vertex or it is dropped with a warning (one vertex without a colour would shift every
// colour after it). Colours are scaled when the file is done: a format may say its scale (PLY's
// uchar is 0-255, its float 0-1); where it does not (OBJ, .xyzrgb), values above 1 mean 0-255.
#pragma once

#include <string>

#include "io/point_reader.hpp"

namespace sculpt::io {

class Attribute_collector {
 public:
  // The scale of the colours given, where the format says it: 255 (bytes), 65535 (16-bit
  // levels, LAS) or 1 (fractions); 0 decides by the largest value.
  explicit Attribute_collector(double color_scale = 0) : color_scale_(color_scale) {}

  // For vertex `vertex` (0-based), given in order.
  void normal(std::size_t vertex, const std::array<double, 3>& n);
  void color(std::size_t vertex, const std::array<double, 3>& rgb);

  // Moves what every vertex had into the set; names what was dropped in its warnings.
  void finish(Point_set& set, const std::string& name);

 private:
  double color_scale_;
  std::vector<std::array<double, 3>> normals_;
  std::vector<std::array<float, 3>> colors_;
  bool normals_gap_ = false, colors_gap_ = false;  // a vertex without one before one with it
  std::size_t not_finite_ = 0;
};

}  // namespace sculpt::io
