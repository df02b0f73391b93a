// SPDX-License-Identifier: GPL-3.0-or-later
#include "polygons.hpp"

#include "io/io_error.hpp"

namespace sculpt::io {

void add_polygon(Point_set& set, const std::vector<int>& corners, const Byte_input& input) {
  for (std::size_t j = 2; j < corners.size(); ++j) {
    input.check_room_for_face(set.triangles.size());
    set.triangles.push_back({corners[0], corners[j - 1], corners[j]});
  }
}

void check_corners(const Point_set& set, const std::string& name, int first_index) {
  for (const auto& triangle : set.triangles) {
    for (int corner : triangle) {
      if (static_cast<std::size_t>(corner) >= set.points.size()) {
        throw Error(name + ": a face names vertex " + std::to_string(corner + first_index) +
                    " of " + std::to_string(set.points.size()));
      }
    }
  }
}

}  // namespace sculpt::io
