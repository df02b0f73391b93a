// SPDX-License-Identifier: GPL-3.0-or-later
// PCD 0.7 (the Point Cloud Library's format): a text header (FIELDS, SIZE, TYPE, COUNT, WIDTH,
// HEIGHT, POINTS, DATA) and the points as text or as fixed-size binary records. The fields x, y
// and z are read, the others (rgb, normals, intensity) read past. An organized cloud marks the
// pixels without a measurement with NaN: those points are skipped, and counted in a warning.
// LZF-compressed data (DATA binary_compressed) has no Debian decoder: refused with one line.
#include <cmath>
#include <cstring>

#include "core/point_names.hpp"
#include "formats.hpp"
#include "io/io_error.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

struct Field {
  std::string name;
  std::uint64_t size = 4, count = 1;
  char type = 'F';
};

// One value of a binary record, little endian as PCL writes it.
double binary_value(const unsigned char* bytes, const Field& field) {
  std::uint64_t bits = 0;
  for (int k = static_cast<int>(field.size) - 1; k >= 0; --k) bits = bits << 8 | bytes[k];
  if (field.type == 'F') {
    if (field.size == 4) {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float value;
      std::memcpy(&value, &narrow, 4);
      return value;
    }
    double value;
    std::memcpy(&value, &bits, 8);
    return value;
  }
  if (field.type == 'U') return static_cast<double>(bits);
  const int shift = 64 - 8 * static_cast<int>(field.size);  // sign-extend
  return static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
}

}  // namespace

Point_set read_pcd(Byte_input& input) {
  std::vector<Field> fields;
  std::uint64_t points = 0, width = 0, height = 1;
  bool have_points = false, have_width = false;
  std::string data, line;
  long line_number = 0;
  std::vector<std::string_view> words;
  const auto where = [&] { return input.name() + " line " + std::to_string(line_number); };
  input.skip_byte_order_mark();
  while (data.empty()) {
    if (!input.read_line(line, 4096)) throw Error(input.name() + " ends before its DATA line");
    ++line_number;
    line.erase(std::min(line.size(), line.find('#')));  // a comment; words view the line
    split_words(line, words);
    if (words.empty()) continue;
    const std::string key(words[0]);
    const std::size_t values = words.size() - 1;
    const auto count_of = [&](std::size_t k) {
      std::uint64_t value = 0;
      if (!parse_count(words[k], value)) {
        throw Error(where() + ": '" + printable(words[k]) + "' is not a count");
      }
      return value;
    };
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    if (key == "FIELDS") {
      fields.assign(values, Field{});
      for (std::size_t k = 0; k < values; ++k) fields[k].name = std::string(words[k + 1]);
    } else if (key == "SIZE" || key == "TYPE" || key == "COUNT") {
      if (values != fields.size()) {
        throw Error(where() + ": " + key + " gives " + std::to_string(values) + " values for " +
                    std::to_string(fields.size()) + " fields");
      }
      for (std::size_t k = 0; k < values; ++k) {
        if (key == "TYPE") {
          if (words[k + 1].size() != 1 ||
              std::string_view("FIU").find(words[k + 1][0]) == std::string_view::npos) {
            throw Error(where() + ": TYPE '" + printable(words[k + 1]) + "' is not F, I or U");
          }
          fields[k].type = words[k + 1][0];
        } else if (key == "SIZE") {
          fields[k].size = count_of(k + 1);
        } else {
          fields[k].count = count_of(k + 1);
        }
      }
    } else if (key == "WIDTH" && values == 1) {
      width = count_of(1);
      have_width = true;
    } else if (key == "HEIGHT" && values == 1) {
      height = count_of(1);
    } else if (key == "POINTS" && values == 1) {
      points = count_of(1);
      have_points = true;
    } else if (key == "DATA" && values == 1) {
      data = std::string(words[1]);
    } else {
      throw Error(where() + ": '" + printable(words[0]) + "' is not a PCD header line");
    }
  }
  if (!have_points) points = have_width ? width * height : 0;
  if (have_width && (height == 0 || width > points / height || width * height != points)) {
    throw Error(input.name() + ": WIDTH x HEIGHT is not POINTS");
  }
  if (data == "binary_compressed") {
    throw Error(input.name() +
                " holds LZF-compressed points (DATA binary_compressed), which Sculpt cannot "
                "read: no Debian package decodes them; save it as binary or ascii PCD");
  }
  if (data != "ascii" && data != "binary") {
    throw Error(input.name() + ": DATA '" + printable(data) + "' is not ascii or binary");
  }
  // Where x, y and z are in a record: the value index (text) and the byte offset (binary).
  std::uint64_t record_bytes = 0, record_values = 0;
  int axis_field[3] = {-1, -1, -1};
  std::uint64_t axis_value[3] = {}, axis_byte[3] = {};
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const Field& field = fields[f];
    const bool float_size = field.size == 4 || field.size == 8;
    if (field.count == 0 || field.count > 1 << 20 ||
        !(field.type == 'F'
              ? float_size
              : field.size == 1 || field.size == 2 || field.size == 4 || field.size == 8)) {
      throw Error(input.name() + ": field '" + printable(field.name) +
                  "' has a size, type or count"
                  " PCD does not define");
    }
    for (int k = 0; k < 3; ++k) {
      if (field.name == std::string(1, "xyz"[k])) {
        if (field.count != 1)
          throw Error(input.name() + ": the field " + field.name + " has COUNT " +
                      std::to_string(field.count));
        axis_field[k] = static_cast<int>(f);
        axis_value[k] = record_values;
        axis_byte[k] = record_bytes;
      }
    }
    record_values += field.count;
    record_bytes += field.size * field.count;
  }
  for (int k = 0; k < 3; ++k) {
    if (axis_field[k] < 0) {
      throw Error(input.name() + " has no field " + std::string(1, "xyz"[k]) +
                  " (FIELDS names the columns)");
    }
  }
  input.check_count(points, data == "binary" ? record_bytes : 2 * record_values, "PCD points");

  Point_set set;
  set.dimension = 3;
  std::uint64_t unmeasured = 0;
  const auto add = [&](const Point<3>& point, std::uint64_t index) {
    if (std::isnan(point[0]) || std::isnan(point[1]) || std::isnan(point[2])) {
      ++unmeasured;  // an organized cloud's pixel without a return
      return;
    }
    if (!std::isfinite(point[0]) || !std::isfinite(point[1]) || !std::isfinite(point[2])) {
      throw Error(input.name() + ": " + ordinal_point(index) +
                  " has a coordinate that is infinite");
    }
    add_vertex(set, point, input);
  };
  if (data == "binary") {
    std::vector<unsigned char> record(record_bytes);
    for (std::uint64_t i = 0; i < points; ++i) {
      input.read(record.data(), record.size(), "a PCD point record");
      Point<3> point;
      for (int k = 0; k < 3; ++k)
        point[k] = binary_value(record.data() + axis_byte[k], fields[axis_field[k]]);
      add(point, i);
    }
    if (!input.at_end()) {
      throw Error(input.name() + ": data after the " + std::to_string(points) +
                  " points its header announces (at byte " + std::to_string(input.offset()) + ")");
    }
  } else {
    Text_lines lines(input, "an ASCII PCD body", line_number);
    std::uint64_t i = 0;
    while (lines.next(words, 0)) {
      if (words.empty()) continue;
      if (i == points) throw Error(lines.where() + ": data after the points the header announces");
      if (words.size() != record_values) {
        throw Error(lines.where() + ": expected " + std::to_string(record_values) +
                    " values, found " + std::to_string(words.size()));
      }
      Point<3> point;
      for (int k = 0; k < 3; ++k) {
        const std::string_view word = words[axis_value[k]];
        if (same_word(word, "nan")) {
          point[k] = std::nan("");
        } else if (!parse_number(word, point[k])) {
          throw Error(lines.where() + ": '" + printable(word) + "' is not a number");
        }
      }
      add(point, i++);
    }
    if (i != points) {
      throw Error(input.name() + " is truncated: its header announces " + std::to_string(points) +
                  " points, it holds " + std::to_string(i));
    }
  }
  if (unmeasured > 0) {
    set.warnings.push_back(input.name() + ": " + std::to_string(unmeasured) +
                           " points without a measurement (NaN) skipped");
  }
  return set;
}

}  // namespace sculpt::io
