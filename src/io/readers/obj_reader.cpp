// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ: `v x y z [w]` vertices (a colour after them is ignored) and `f` faces whose
// corners are `i`, `i/t`, `i//n` or `i/t/n`, negative indices counting back from the last
// vertex. Every other record (normals, texture coordinates, groups, materials, lines) is read
// past, so a point cloud of `v` lines alone is a valid OBJ.
#include <cmath>
#include <limits>

#include "formats.hpp"
#include "io/io_error.hpp"
#include "polygons.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {

Point_set read_obj(Byte_input& input) {
  Text_lines lines(input, "an OBJ file");
  std::vector<std::string_view> words;
  Point_set set;
  set.dimension = 3;
  std::vector<int> polygon;
  while (lines.next(words, '#')) {
    if (words.empty()) continue;
    if (words[0] == "v") {
      if (words.size() < 4) throw Error(lines.where() + ": a vertex needs x, y and z");
      Point<3> point{0, 0, 0};
      for (std::size_t k = 1; k < words.size(); ++k) {
        double value = 0;
        if (!parse_number(words[k], value)) {
          throw Error(lines.where() + ": '" + printable(words[k]) + "' is not a number");
        }
        if (k <= 3) {
          if (!std::isfinite(value)) {
            throw Error(lines.where() + ": coordinate '" + printable(words[k]) + "' is not finite");
          }
          point[k - 1] = value;
        }
      }
      add_vertex(set, point, input);
    } else if (words[0] == "f") {
      if (words.size() < 4) throw Error(lines.where() + ": a face needs at least 3 corners");
      polygon.clear();
      for (std::size_t k = 1; k < words.size(); ++k) {
        const std::string_view corner = words[k].substr(0, words[k].find('/'));
        std::int64_t index = 0;
        if (!parse_integer(corner, index) || index == 0) {
          throw Error(lines.where() + ": '" + printable(words[k]) + "' is not a vertex index");
        }
        // 1-based; negative counts back from the last vertex read so far.
        const std::int64_t vertex =
            index > 0 ? index - 1 : static_cast<std::int64_t>(set.points.size()) + index;
        if (vertex < 0 || vertex > std::numeric_limits<int>::max()) {
          throw Error(lines.where() + ": face corner '" + printable(words[k]) +
                      "' names no vertex");
        }
        polygon.push_back(static_cast<int>(vertex));
      }
      add_polygon(set, polygon, input);
    }
  }
  check_corners(set, input.name(), 1);
  return set;
}

}  // namespace sculpt::io
