// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ: `v x y z [w]` vertices (or `v x y z r g b`, the vertex colours MeshLab and
// Open3D write) and `f` faces whose corners are `i`, `i/t`, `i//n` or `i/t/n`, negative indices
// counting back from the last vertex. `vn` normals are kept when there is one per vertex (as
// point clouds are written: the i-th normal is the i-th vertex's). Every other record (texture
// coordinates, groups, materials, lines) is read past, so a point cloud of `v` lines alone is a
// valid OBJ.
#include <cmath>
#include <limits>

#include "attribute_collector.hpp"
#include "formats.hpp"
#include "io/io_error.hpp"
#include "polygons.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

// The numbers after a record's keyword; throws on a word that is not one.
void numbers_of(const std::vector<std::string_view>& words, const Text_lines& lines,
                std::vector<double>& numbers) {
  numbers.clear();
  for (std::size_t k = 1; k < words.size(); ++k) {
    double value = 0;
    if (!parse_number(words[k], value)) {
      throw Error(lines.where() + ": '" + printable(words[k]) + "' is not a number");
    }
    numbers.push_back(value);
  }
}

}  // namespace

Point_set read_obj(Byte_input& input) {
  Text_lines lines(input, "an OBJ file");
  std::vector<std::string_view> words;
  std::vector<double> numbers;
  Point_set set;
  set.dimension = 3;
  std::vector<int> polygon;
  Attribute_collector attributes;
  std::vector<std::array<double, 3>> normals;
  while (lines.next(words, '#')) {
    if (words.empty()) continue;
    if (words[0] == "v") {
      if (words.size() < 4) throw Error(lines.where() + ": a vertex needs x, y and z");
      numbers_of(words, lines, numbers);
      Point<3> point{numbers[0], numbers[1], numbers[2]};
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(point[k])) {
          throw Error(lines.where() + ": coordinate '" + printable(words[k + 1]) +
                      "' is not finite");
        }
      }
      add_vertex(set, point, input);
      if (numbers.size() == 6) {
        attributes.color(set.points.size() - 1, {numbers[3], numbers[4], numbers[5]});
      }
    } else if (words[0] == "vn") {
      if (words.size() != 4) throw Error(lines.where() + ": a normal needs x, y and z");
      numbers_of(words, lines, numbers);
      input.check_room_for_point(normals.size());  // no more normals than points may be held
      normals.push_back({numbers[0], numbers[1], numbers[2]});
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
  if (normals.size() == set.points.size()) {
    for (std::size_t i = 0; i < normals.size(); ++i) attributes.normal(i, normals[i]);
  } else if (!normals.empty()) {
    set.warnings.push_back(input.name() + ": " + std::to_string(normals.size()) + " normals for " +
                           std::to_string(set.points.size()) +
                           " vertices; normals are kept only when there is one per vertex");
  }
  attributes.finish(set, input.name());
  return set;
}

}  // namespace sculpt::io
