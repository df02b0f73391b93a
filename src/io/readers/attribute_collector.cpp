// SPDX-License-Identifier: GPL-3.0-or-later
#include "attribute_collector.hpp"

#include <algorithm>
#include <cmath>

namespace sculpt::io {

void Attribute_collector::normal(std::size_t vertex, const std::array<double, 3>& n) {
  if (normals_.size() != vertex) normals_gap_ = true;
  std::array<double, 3> kept = n;
  if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) {
    ++not_finite_;  // scanners write NaN where they found no plane (PCL): no direction
    kept = {0, 0, 0};
  }
  normals_.push_back(kept);
}

void Attribute_collector::color(std::size_t vertex, const std::array<double, 3>& rgb) {
  if (colors_.size() != vertex) colors_gap_ = true;
  colors_.push_back(
      {static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])});
}

void Attribute_collector::finish(Point_set& set, const std::string& name) {
  const std::size_t points = set.points.size();
  auto dropped = [&](std::size_t given, const char* what) {
    set.warnings.push_back(name + ": " + std::to_string(given) + " of " + std::to_string(points) +
                           " points have " + what + "; " + what + " not kept");
  };
  if (!normals_.empty() && (normals_.size() != points || normals_gap_)) {
    dropped(normals_.size(), "normals");
  } else if (!normals_.empty()) {
    if (not_finite_ > 0) {
      set.warnings.push_back(name + ": " + std::to_string(not_finite_) +
                             " normals are not finite numbers; kept as (0, 0, 0)");
    }
    set.attributes.normals = std::move(normals_);
  }
  if (!colors_.empty() && (colors_.size() != points || colors_gap_)) {
    dropped(colors_.size(), "colours");
  } else if (!colors_.empty()) {
    double scale = color_scale_;
    if (scale == 0) {
      float largest = 0;
      for (const auto& c : colors_) largest = std::max({largest, c[0], c[1], c[2]});
      scale = largest > 1 ? 255 : 1;
    }
    set.attributes.colors.reserve(points);
    for (const auto& c : colors_) {
      std::array<std::uint8_t, 3> level{};
      for (int k = 0; k < 3; ++k) {
        const double fraction = std::isfinite(c[k]) ? std::clamp(c[k] / scale, 0.0, 1.0) : 0.0;
        level[k] = static_cast<std::uint8_t>(std::lround(fraction * 255));
      }
      set.attributes.colors.push_back(level);
    }
  }
  normals_.clear();
  colors_.clear();
}

}  // namespace sculpt::io
