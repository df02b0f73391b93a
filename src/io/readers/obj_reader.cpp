// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ: `v x y z [w]` vertices (or `v x y z r g b`, the vertex colours MeshLab and
// Open3D write) and `f` faces whose corners are `i`, `i/t`, `i//n` or `i/t/n`, negative indices
// counting back from the last vertex. `vn` normals are kept when there is one per vertex and no
// face corner names another normal for its vertex (`i//n` with n = i, as point clouds and
// Sculpt's own surfaces are written): the i-th normal is then the i-th vertex's. Every other
// record (texture
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
  bool normals_per_corner = false;  // a corner names a normal other than its vertex's
  bool too_many_normals = false;    // more than the points a file may hold: none kept
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
      if (!too_many_normals) {
        try {
          input.check_room_for_point(normals.size());  // no more normals than points are held
          normals.push_back({numbers[0], numbers[1], numbers[2]});
        } catch (const Error&) {
          too_many_normals = true;
          std::vector<std::array<double, 3>>().swap(normals);
        }
      }
    } else if (words[0] == "f") {
      if (words.size() < 4) throw Error(lines.where() + ": a face needs at least 3 corners");
      polygon.clear();
      for (std::size_t k = 1; k < words.size(); ++k) {
        const std::size_t slash = words[k].find('/');
        const std::string_view corner = words[k].substr(0, slash);
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
        // i//n or i/t/n: the normal this corner uses, which must be its vertex's own.
        const std::size_t second = slash == std::string_view::npos ? std::string_view::npos
                                                                   : words[k].find('/', slash + 1);
        if (second != std::string_view::npos && second + 1 < words[k].size()) {
          std::int64_t normal = 0;
          if (!parse_integer(words[k].substr(second + 1), normal)) {
            normals_per_corner = true;
          } else {
            const std::int64_t n =
                normal > 0 ? normal - 1 : static_cast<std::int64_t>(normals.size()) + normal;
            normals_per_corner = normals_per_corner || n != vertex;
          }
        }
      }
      add_polygon(set, polygon, input);
    }
  }
  check_corners(set, input.name(), 1);
  if (!too_many_normals && !normals_per_corner && normals.size() == set.points.size()) {
    for (std::size_t i = 0; i < normals.size(); ++i) attributes.normal(i, normals[i]);
  } else if (!normals.empty() || too_many_normals) {
    set.warnings.push_back(input.name() + ": " +
                           (normals_per_corner
                                ? std::string("faces name normals per corner")
                                : std::to_string(normals.size()) + " normals for " +
                                      std::to_string(set.points.size()) + " vertices") +
                           "; normals are kept only when there is one per vertex");
  }
  attributes.finish(set, input.name());
  return set;
}

}  // namespace sculpt::io
