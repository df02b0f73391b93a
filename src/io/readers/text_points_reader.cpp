// SPDX-License-Identifier: GPL-3.0-or-later
// Point lists as scanners and people write them: one point per line, numbers separated by
// spaces, tabs, commas or semicolons; `#` comments; a leading `p` or `v` (Hoppe's .pts, OBJ-like
// lists); an optional count on the first line. Columns after x y z are a normal or a colour as
// the format says (Text_columns); other extra columns are read past.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "attribute_collector.hpp"
#include "formats.hpp"
#include "io/io_error.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// A number written with a decimal comma ("1,5") in a line whose fields are apart by spaces, tabs
// or semicolons, as spreadsheets in much of Europe save them; empty if there is none. Taking
// its comma for a separator would make two numbers of one and shift every coordinate after it.
std::string_view decimal_comma_field(std::string_view line) {
  line = line.substr(0, line.find('#'));
  if (line.find(',') == std::string_view::npos) return {};
  const std::size_t first = line.find_first_not_of(" \t\r;");
  if (first == std::string_view::npos) return {};
  line = line.substr(first, line.find_last_not_of(" \t\r;") + 1 - first);
  if (line.find_first_of(" \t;") == std::string_view::npos) return {};  // commas part fields
  std::size_t start = 0;
  while (start < line.size()) {
    const std::size_t end = std::min(line.find_first_of(" \t;\r", start), line.size());
    const std::string_view field = line.substr(start, end - start);
    // One number with one comma between digits; "1,2,3" is three numbers.
    const std::size_t comma = field.find(',');
    if (comma != std::string_view::npos && field.find(',', comma + 1) == std::string_view::npos &&
        comma > 0 && comma + 1 < field.size() && is_digit(field[comma - 1]) &&
        is_digit(field[comma + 1]))
      return field;
    start = end + 1;
  }
  return {};
}

// Three values after x y z that are whole numbers from 0 to 255, some above 1, are colour
// levels; a normal's components are fractions of at most 1 in size.
bool look_like_color_levels(const std::vector<std::array<double, 3>>& triples) {
  bool above_one = false;
  for (const auto& t : triples) {
    for (double v : t) {
      if (!(v >= 0 && v <= 255 && v == std::floor(v))) return false;
      above_one = above_one || v > 1;
    }
  }
  return above_one;
}

// Where the triple after the coordinates starts on a line of `count` numbers, or 0 for none.
std::size_t triple_start(Text_columns columns, std::size_t count) {
  switch (columns) {
    case Text_columns::coordinates:
      return 0;
    case Text_columns::leica:  // x y z intensity r g b, or x y z r g b
      return count >= 7 ? 4 : count == 6 ? 3 : 0;
    case Text_columns::by_values:
      return count == 6 ? 3 : 0;
    default:
      return count >= 6 ? 3 : 0;
  }
}

// The triples become normals or colours; a file with them on some lines only keeps none.
void keep_attributes(Point_set& set, const std::string& name, Text_columns columns,
                     const std::vector<std::array<double, 3>>& triples, bool on_every_line) {
  if (triples.empty()) return;
  if (!on_every_line || triples.size() != set.points.size()) {
    set.warnings.push_back(name + ": " + std::to_string(triples.size()) + " of " +
                           std::to_string(set.points.size()) +
                           " lines have a normal or colour after x y z; none kept");
    return;
  }
  const bool colors = columns == Text_columns::colors || columns == Text_columns::leica ||
                      (columns == Text_columns::by_values && look_like_color_levels(triples));
  Attribute_collector attributes(columns == Text_columns::leica ? 255 : 0);
  for (std::size_t i = 0; i < triples.size(); ++i) {
    if (colors) {
      attributes.color(i, triples[i]);
    } else {
      attributes.normal(i, triples[i]);
    }
  }
  attributes.finish(set, name);
}

}  // namespace

Point_set read_text_points(Byte_input& input, int forced_dimension, Text_columns extra) {
  Text_lines lines(input, "a text point file");
  Point_set set;
  set.dimension = forced_dimension ? forced_dimension : 3;
  std::vector<std::string_view> words;
  std::vector<double> numbers;
  std::uint64_t announced = 0;
  bool has_count = false;
  std::size_t columns = 0;       // numbers on every point line, from the first one
  std::string first_point_line;  // where that was, for the message on a line that differs
  std::vector<std::array<double, 3>> triples;  // the values after x y z, where there are some
  bool every_line_has_a_triple = true;
  bool with_intensity = false;  // Leica's seven columns: the triple is a colour
  while (lines.next(words, '#', ",;")) {
    if (words.empty()) continue;
    std::size_t first = 0;
    double value = 0;
    if (is_letter(words[0][0]) && !parse_number(words[0], value)) {
      // `p x y z` and `v x y z` are points; other records (a scanner's d, s, g lines, `vn`
      // normals, a header of column names) are not.
      if (words[0] != "p" && words[0] != "v" && words[0] != "P" && words[0] != "V") continue;
      first = 1;
    }
    if (const auto field = decimal_comma_field(lines.line()); !field.empty()) {
      throw Error(lines.where() + ": '" + printable(field) +
                  "' is written with a decimal comma; Sculpt reads a decimal point (1.5, not "
                  "1,5): replace the commas first, e.g. sed 's/,/./g'");
    }
    numbers.clear();
    for (std::size_t k = first; k < words.size(); ++k) {
      if (!parse_number(words[k], value)) {
        throw Error(lines.where() + ": '" + printable(words[k]) + "' is not a number");
      }
      numbers.push_back(value);
    }
    if (numbers.empty()) continue;
    std::uint64_t count = 0;
    if (set.points.empty() && !has_count && columns == 0 && numbers.size() == 1 &&
        parse_count(words[first], count)) {
      has_count = true;  // a count header: digits alone on the first line with numbers
      announced = count;
      input.check_count(announced, 4, "points");  // "0 0\n" (the last may lack its \n)
      continue;
    }
    if (columns == 0) {
      columns = numbers.size();
      first_point_line = lines.where();
      set.dimension = forced_dimension ? forced_dimension : (columns >= 3 ? 3 : 2);
      if (columns < static_cast<std::size_t>(set.dimension)) {
        // Two numbers a line are a plane curve, which this extension does not hold (.xyz).
        const std::string hint =
            columns == 2 ? " (a plane curve: name the file .xy, .txt or .csv)" : "";
        throw Error(lines.where() + ": expected " + std::to_string(set.dimension) +
                    " coordinates, found " + std::to_string(columns) + hint);
      }
    } else if (numbers.size() < static_cast<std::size_t>(set.dimension) ||
               (!forced_dimension && columns == 2 && numbers.size() > 2)) {
      // Columns after the coordinates may vary; the coordinates may not: a third number where
      // the first point line had two would be a z that is silently dropped.
      throw Error(lines.where() + " holds " + std::to_string(numbers.size()) + " numbers, but " +
                  first_point_line + " held " + std::to_string(columns) +
                  " (mixed columns: 2D or 3D?)");
    }
    Point<3> p{0, 0, 0};
    for (int k = 0; k < set.dimension; ++k) {
      if (!std::isfinite(numbers[k])) {
        throw Error(lines.where() + ": coordinate '" + printable(words[first + k]) +
                    "' is not finite");
      }
      p[k] = numbers[k];
    }
    add_vertex(set, p, input);
    if (set.dimension == 3) {
      if (const std::size_t start = triple_start(extra, numbers.size()); start > 0) {
        with_intensity = with_intensity || start == 4;
        triples.push_back({numbers[start], numbers[start + 1], numbers[start + 2]});
      } else {
        every_line_has_a_triple = false;
      }
    }
  }
  if (has_count && announced != set.points.size()) {
    throw Error(input.name() + " is truncated or malformed: its first line announces " +
                std::to_string(announced) + " points, it holds " +
                std::to_string(set.points.size()));
  }
  // Six columns of a .pts are colours or normals as their values show, as in an .xyz.
  const Text_columns kept =
      extra == Text_columns::leica && !with_intensity ? Text_columns::by_values : extra;
  keep_attributes(set, input.name(), kept, triples, every_line_has_a_triple);
  return set;
}

}  // namespace sculpt::io
