// SPDX-License-Identifier: GPL-3.0-or-later
// OFF (Geomview): a keyword `[ST][C][N][4][n]OFF`, the counts, one vertex per line (texture
// coordinates, colours and normals after the coordinates are ignored), one face per line
// (its corner count, the corners, maybe a colour). Text only; `#` starts a comment.
#include <algorithm>
#include <cmath>

#include "formats.hpp"
#include "io/io_error.hpp"
#include "polygons.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

struct Keyword {
  bool homogeneous = false;      // 4OFF: a last coordinate w divides the others
  bool dimension_given = false;  // nOFF: the space dimension follows the keyword
};

// Parses [ST][C][N][4][n]OFF; false if the word is not an OFF keyword.
bool parse_keyword(std::string_view word, Keyword& keyword) {
  for (std::string_view prefix : {"ST", "C", "N"}) {
    if (word.substr(0, prefix.size()) == prefix) word.remove_prefix(prefix.size());
  }
  if (!word.empty() && word[0] == '4') {
    keyword.homogeneous = true;
    word.remove_prefix(1);
  }
  if (!word.empty() && word[0] == 'n') {
    keyword.dimension_given = true;
    word.remove_prefix(1);
  }
  return word == "OFF";
}

}  // namespace

Point_set read_off(Byte_input& input) {
  Text_lines lines(input, "an OFF file");
  std::vector<std::string_view> words;
  auto next_content_line = [&](const char* what) {
    do {
      if (!lines.next(words, '#')) {
        throw Error(input.name() + " is truncated: it ends before " + std::string(what));
      }
    } while (words.empty());
  };

  next_content_line("its OFF keyword");
  Keyword keyword;
  if (!parse_keyword(words[0], keyword)) {
    throw Error(input.name() + " is not an OFF file (it does not start with OFF)");
  }
  std::vector<std::string> header(words.begin() + 1, words.end());
  if (!header.empty() && header[0] == "BINARY") {
    throw Error(input.name() +
                " is a binary OFF file, which Sculpt does not read (save it as text)");
  }
  int dimension = 3;
  if (keyword.dimension_given) {
    if (header.empty()) {
      next_content_line("its dimension");
      header.assign(words.begin(), words.end());
    }
    std::uint64_t given = 0;
    if (!parse_count(header[0], given) || (given != 2 && given != 3)) {
      throw Error(lines.where() + ": an nOFF dimension of 2 or 3 was expected, not '" +
                  printable(header[0]) + "'");
    }
    dimension = static_cast<int>(given);
    header.erase(header.begin());
  }
  if (header.empty()) {
    next_content_line("its vertex and face counts");
    header.assign(words.begin(), words.end());
  }
  std::uint64_t vertices = 0, faces = 0, edges = 0;
  if (header.size() < 2 || header.size() > 3 || !parse_count(header[0], vertices) ||
      !parse_count(header[1], faces) || (header.size() == 3 && !parse_count(header[2], edges))) {
    throw Error(lines.where() + ": expected the counts 'VERTICES FACES EDGES'");
  }
  input.check_count(vertices, 2 * dimension, "vertices");  // "0 0 0\n" (3D), "0 0\n" (2D)
  input.check_count(faces, 2, "faces");                    // "0\n"

  Point_set set;
  set.dimension = dimension;
  set.points.reserve(std::min<std::uint64_t>(vertices, 1 << 20));
  const std::size_t coordinates = dimension + (keyword.homogeneous ? 1 : 0);
  for (std::uint64_t i = 0; i < vertices; ++i) {
    next_content_line(("vertex " + std::to_string(i) + " of " + std::to_string(vertices)).c_str());
    if (words.size() < coordinates) {
      throw Error(lines.where() + ": vertex " + std::to_string(i) + " has " +
                  std::to_string(words.size()) + " numbers, not " + std::to_string(coordinates));
    }
    double values[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < words.size(); ++k) {
      double value = 0;
      if (!parse_number(words[k], value)) {
        throw Error(lines.where() + ": '" + printable(words[k]) + "' is not a number");
      }
      if (k < coordinates) values[k] = value;
    }
    Point<3> point{0, 0, 0};
    for (int k = 0; k < dimension; ++k) {
      point[k] = keyword.homogeneous ? values[k] / values[dimension] : values[k];
      if (!std::isfinite(point[k])) {
        throw Error(lines.where() + ": vertex " + std::to_string(i) +
                    " has a coordinate that is not finite");
      }
    }
    add_vertex(set, point, input);
  }
  std::vector<int> polygon;
  for (std::uint64_t f = 0; f < faces; ++f) {
    next_content_line(("face " + std::to_string(f) + " of " + std::to_string(faces)).c_str());
    std::uint64_t corners = 0;
    if (!parse_count(words[0], corners) || corners > words.size() - 1) {
      throw Error(lines.where() + ": face " + std::to_string(f) + " should start with its corner " +
                  "count and list that many vertices");
    }
    polygon.clear();
    for (std::size_t k = 1; k <= corners; ++k) {
      std::uint64_t corner = 0;
      if (!parse_count(words[k], corner) || corner >= vertices) {
        throw Error(lines.where() + ": face " + std::to_string(f) + " names vertex '" +
                    printable(words[k]) + "' of " + std::to_string(vertices));
      }
      polygon.push_back(static_cast<int>(corner));
    }
    add_polygon(set, polygon, input);
  }
  while (lines.next(words, '#')) {
    if (!words.empty()) throw Error(lines.where() + ": data after the last face");
  }
  return set;
}

}  // namespace sculpt::io
