// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// What a scan carries beside its points: a normal and a colour per point. The readers keep them
/// (PLY, OBJ, .pwn/.xyz/.xyzn normals, .pts/.xyzrgb colours), --merge-duplicates keeps the first
/// occurrence's, and the PLY and OBJ writers put them on the surface's vertices, which are the
/// samples. Each list is empty or holds one entry per point, in the points' order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

struct Point_attributes {
  std::vector<std::array<double, 3>> normals;       ///< as given: not normalised, not oriented
  std::vector<std::array<std::uint8_t, 3>> colors;  ///< red, green, blue from 0 to 255

  bool empty() const { return normals.empty() && colors.empty(); }
};

}  // namespace sculpt
