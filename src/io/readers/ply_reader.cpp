// SPDX-License-Identifier: GPL-3.0-or-later
// PLY (Turk 1994): a text header declaring elements and their typed properties, then the
// elements in ASCII or binary (either byte order). Coordinates may have any scalar type; every
// element count and list length is checked against the bytes that can follow it; elements
// other than `vertex` and `face` are read past. A vertex's nx ny nz and red green blue (or
// diffuse_red ...) are kept: colours as bytes, 16-bit levels or 0-1 fractions by their type.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "attribute_collector.hpp"
#include "formats.hpp"
#include "io/io_error.hpp"
#include "polygons.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

enum class Scalar { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<Scalar> scalar_named(std::string_view name) {
  struct Named {
    const char* name;
    Scalar type;
  };
  static const Named names[] = {
      {"char", Scalar::int8},      {"int8", Scalar::int8},       {"uchar", Scalar::uint8},
      {"uint8", Scalar::uint8},    {"short", Scalar::int16},     {"int16", Scalar::int16},
      {"ushort", Scalar::uint16},  {"uint16", Scalar::uint16},   {"int", Scalar::int32},
      {"int32", Scalar::int32},    {"uint", Scalar::uint32},     {"uint32", Scalar::uint32},
      {"float", Scalar::float32},  {"float32", Scalar::float32}, {"double", Scalar::float64},
      {"float64", Scalar::float64}};
  for (const auto& named : names) {
    if (name == named.name) return named.type;
  }
  return std::nullopt;
}

std::size_t size_of(Scalar type) {
  switch (type) {
    case Scalar::int8:
    case Scalar::uint8:
      return 1;
    case Scalar::int16:
    case Scalar::uint16:
      return 2;
    case Scalar::int32:
    case Scalar::uint32:
    case Scalar::float32:
      return 4;
    case Scalar::float64:
      return 8;
  }
  return 8;
}

bool is_integral(Scalar type) {
  return type != Scalar::float32 && type != Scalar::float64;
}

struct Property {
  std::string name;
  Scalar type = Scalar::float32;  // of the value, or of a list's items
  bool is_list = false;
  Scalar count_type = Scalar::uint8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { ascii, little_endian, big_endian };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  long lines = 0;
};

Header read_header(Byte_input& input) {
  constexpr std::uint64_t max_header_bytes = 1 << 20;
  Header header;
  input.skip_byte_order_mark();
  std::string line;
  std::vector<std::string_view> words;
  bool has_format = false;
  auto where = [&] { return input.name() + " line " + std::to_string(header.lines); };
  for (;;) {
    if (!input.read_line(line, 1 << 16)) {
      throw Error(input.name() + " ends inside its PLY header");
    }
    ++header.lines;
    if (looks_binary(line)) {
      throw Error(header.lines == 1
                      ? input.name() + " is not a PLY file (it does not start with 'ply')"
                      : where() + ": binary data inside the PLY header");
    }
    if (input.offset() > max_header_bytes) throw Error(input.name() + ": a PLY header over 1 MiB");
    split_words(line, words);
    if (header.lines == 1) {
      if (words.size() != 1 || words[0] != "ply") {
        throw Error(input.name() + " is not a PLY file (it does not start with 'ply')");
      }
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    const std::string_view keyword = words[0];
    if (keyword == "end_header") break;
    if (keyword == "format") {
      if (words.size() < 2) throw Error(where() + ": a format line without a format");
      if (words[1] == "ascii") {
        header.encoding = Encoding::ascii;
      } else if (words[1] == "binary_little_endian") {
        header.encoding = Encoding::little_endian;
      } else if (words[1] == "binary_big_endian") {
        header.encoding = Encoding::big_endian;
      } else {
        throw Error(where() + ": unknown PLY format '" + printable(words[1]) + "'");
      }
      has_format = true;
    } else if (keyword == "element") {
      Element element;
      if (words.size() != 3 || !parse_count(words[2], element.count)) {
        throw Error(where() + ": expected 'element NAME COUNT' with COUNT a whole number");
      }
      element.name = words[1];
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) throw Error(where() + ": a property before any element");
      Property property;
      std::optional<Scalar> type, count_type;
      if (words.size() == 5 && words[1] == "list") {
        count_type = scalar_named(words[2]);
        type = scalar_named(words[3]);
        if (!count_type || !is_integral(*count_type)) {
          throw Error(where() + ": a list's length type must be an integer type");
        }
        property.is_list = true;
        property.count_type = *count_type;
        property.name = words[4];
      } else if (words.size() == 3) {
        type = scalar_named(words[1]);
        property.name = words[2];
      }
      if (!type) throw Error(where() + ": expected 'property TYPE NAME' with a PLY scalar type");
      property.type = *type;
      header.elements.back().properties.push_back(property);
    } else {
      throw Error(where() + ": unknown PLY header line '" + printable(keyword) + "'");
    }
  }
  if (!has_format) throw Error(input.name() + ": the PLY header has no format line");
  return header;
}

// Reads the values of the elements one by one, whatever the encoding.
class Value_reader {
 public:
  Value_reader(Byte_input& input, Encoding encoding, long header_lines)
      : input_(input), encoding_(encoding) {
    if (encoding_ == Encoding::ascii) lines_.emplace(input, "an ASCII PLY body", header_lines);
  }

  double read(Scalar type, const char* what) {
    return encoding_ == Encoding::ascii ? read_word(type, what) : read_binary(type, what);
  }

  // After the last element only white space may follow. A binary file may end in padding that
  // other tools write and read past (a line end, zeros to a block): accepted, with a warning
  // (returned); any other byte is refused.
  std::string expect_end() {
    if (encoding_ == Encoding::ascii) {
      if (next_word_ < words_.size())
        throw Error(lines_->where() + ": data after the last element");
      while (lines_->next(words_, 0)) {
        if (!words_.empty()) throw Error(lines_->where() + ": data after the last element");
      }
      return "";
    }
    const std::uint64_t end_of_data = input_.offset();
    std::uint64_t padding = 0;
    for (std::string_view bytes = input_.peek(4096); !bytes.empty(); bytes = input_.peek(4096)) {
      for (const char byte : bytes) {
        if (byte != '\0' && byte != '\n' && byte != '\r' && byte != ' ' && byte != '\t') {
          throw Error(input_.name() + ": data after the last element (at byte " +
                      std::to_string(end_of_data + padding) + ")");
        }
        ++padding;
      }
      char skipped[4096];
      input_.read(skipped, bytes.size(), "padding");
    }
    if (padding == 0) return "";
    return input_.name() + ": " + std::to_string(padding) +
           " bytes of padding (white space or zeros) after the last element, ignored";
  }

 private:
  double read_word(Scalar type, const char* what) {
    while (next_word_ == words_.size()) {
      if (!lines_->next(words_, 0)) {
        throw Error(input_.name() + " is truncated: it ends inside " + what);
      }
      next_word_ = 0;
    }
    const std::string_view word = words_[next_word_++];
    if (is_integral(type)) {
      // Some writers put "3.0" where an integer belongs: an integral number is accepted.
      std::int64_t value = 0;
      double number = 0;
      bool integer = parse_integer(word, value);
      if (!integer && parse_number(word, number) && std::abs(number) < 9e18 &&
          number == std::trunc(number)) {
        value = static_cast<std::int64_t>(number);
        integer = true;
      }
      if (!integer || !fits(value, type)) {
        throw Error(lines_->where() + ": '" + printable(word) + "' is not a value of " + what);
      }
      return static_cast<double>(value);
    }
    double value = 0;
    if (!parse_number(word, value)) {
      throw Error(lines_->where() + ": '" + printable(word) + "' is not a number");
    }
    if (type == Scalar::float32 && std::isfinite(value) &&
        std::abs(value) > std::numeric_limits<float>::max()) {
      throw Error(lines_->where() + ": '" + printable(word) + "' is beyond the range of a float");
    }
    return type == Scalar::float32 ? static_cast<double>(static_cast<float>(value)) : value;
  }

  static bool fits(std::int64_t value, Scalar type) {
    switch (type) {
      case Scalar::int8:
        return value >= -128 && value <= 127;
      case Scalar::uint8:
        return value >= 0 && value <= 255;
      case Scalar::int16:
        return value >= -32768 && value <= 32767;
      case Scalar::uint16:
        return value >= 0 && value <= 65535;
      case Scalar::int32:
        return value >= INT32_MIN && value <= INT32_MAX;
      case Scalar::uint32:
        return value >= 0 && value <= UINT32_MAX;
      default:
        return true;
    }
  }

  double read_binary(Scalar type, const char* what) {
    unsigned char bytes[8];
    const std::size_t size = size_of(type);
    input_.read(bytes, size, what);
    const bool swap =
        (encoding_ == Encoding::big_endian) == (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
    if (swap) std::reverse(bytes, bytes + size);
    switch (type) {
      case Scalar::int8:
        return as<std::int8_t>(bytes);
      case Scalar::uint8:
        return as<std::uint8_t>(bytes);
      case Scalar::int16:
        return as<std::int16_t>(bytes);
      case Scalar::uint16:
        return as<std::uint16_t>(bytes);
      case Scalar::int32:
        return as<std::int32_t>(bytes);
      case Scalar::uint32:
        return as<std::uint32_t>(bytes);
      case Scalar::float32:
        return as<float>(bytes);
      case Scalar::float64:
        return as<double>(bytes);
    }
    return 0;
  }

  template <class T>
  static double as(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return static_cast<double>(value);
  }

  Byte_input& input_;
  Encoding encoding_;
  std::optional<Text_lines> lines_;
  std::vector<std::string_view> words_;
  std::size_t next_word_ = 0;
};

// Where an element keeps what Sculpt reads: the coordinates, normal and colour of a vertex, the
// corners of a face.
struct Roles {
  int x = -1, y = -1, z = -1;  // property indices of a vertex element
  int normal[3] = {-1, -1, -1};
  int color[3] = {-1, -1, -1};
  int corners = -1;  // the index list of a face element

  bool has_normal() const { return normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0; }
  bool has_color() const { return color[0] >= 0 && color[1] >= 0 && color[2] >= 0; }
};

// The value that a colour property of this type gives to full intensity; 0 for floats, whose
// scale the values show (0-1 as a rule, 0-255 from some writers).
double full_intensity(Scalar type) {
  if (!is_integral(type)) return 0;
  return type == Scalar::uint16 || type == Scalar::int16 ? 65535 : 255;
}

Roles roles_of(const Element& element, const std::string& name) {
  Roles roles;
  for (int k = 0; k < static_cast<int>(element.properties.size()); ++k) {
    const Property& property = element.properties[k];
    if (element.name == "vertex" && !property.is_list) {
      if (property.name == "x") roles.x = k;
      if (property.name == "y") roles.y = k;
      if (property.name == "z") roles.z = k;
      for (int c = 0; c < 3; ++c) {
        const std::string name(1, "xyz"[c]), channel = c == 0 ? "red" : c == 1 ? "green" : "blue";
        if (property.name == "n" + name) roles.normal[c] = k;
        if (property.name == channel || property.name == "diffuse_" + channel) roles.color[c] = k;
      }
    }
    if (element.name == "face" && property.is_list &&
        (property.name == "vertex_indices" || property.name == "vertex_index")) {
      if (!is_integral(property.type)) {
        throw Error(name + ": the face element's vertex indices are not of an integer type");
      }
      roles.corners = k;
    }
  }
  if (element.name == "vertex" && (roles.x < 0 || roles.y < 0 || roles.z < 0)) {
    throw Error(name + ": the PLY vertex element has no x, y and z properties");
  }
  return roles;
}

}  // namespace

Point_set read_ply(Byte_input& input) {
  const Header header = read_header(input);
  const bool binary = header.encoding != Encoding::ascii;
  Value_reader values(input, header.encoding, header.lines);
  std::optional<Attribute_collector> attributes;
  Point_set set;
  set.dimension = 3;
  bool has_vertices = false;
  std::vector<int> polygon;
  for (const Element& element : header.elements) {
    if (element.properties.empty()) {
      if (element.count == 0) continue;
      throw Error(input.name() + ": the PLY element '" + printable(element.name) + "' has " +
                  std::to_string(element.count) + " items but no properties");
    }
    if (element.name == "vertex") {
      if (has_vertices) throw Error(input.name() + ": two PLY vertex elements");
      has_vertices = true;
    }
    // A binary item takes at least the sizes of its values (a list at least its length); an
    // ASCII one is read word by word, so a count beyond the file ends at its truncation.
    if (binary) {
      std::uint64_t least_bytes = 0;
      for (const Property& property : element.properties) {
        least_bytes += size_of(property.is_list ? property.count_type : property.type);
      }
      input.check_count(element.count, least_bytes, "'" + printable(element.name) + "' elements");
    }
    const Roles roles = roles_of(element, input.name());
    if (element.name == "vertex") {
      attributes.emplace(roles.has_color() ? full_intensity(element.properties[roles.color[0]].type)
                                           : 0.0);
    }
    const std::string what = "a '" + printable(element.name) + "' element";
    if (element.name == "vertex" && binary) {  // a count checked against the bytes left
      set.points.reserve(std::min<std::uint64_t>(element.count, 1 << 20));
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {
      Point<3> point{0, 0, 0};
      std::array<double, 3> normal{}, color{};
      polygon.clear();
      for (int k = 0; k < static_cast<int>(element.properties.size()); ++k) {
        const Property& property = element.properties[k];
        if (!property.is_list) {
          const double value = values.read(property.type, what.c_str());
          if (k == roles.x) point[0] = value;
          if (k == roles.y) point[1] = value;
          if (k == roles.z) point[2] = value;
          for (int c = 0; c < 3; ++c) {
            if (k == roles.normal[c]) normal[c] = value;
            if (k == roles.color[c]) color[c] = value;
          }
          continue;
        }
        const double length = values.read(property.count_type, what.c_str());
        if (length < 0) {
          throw Error(input.name() + ": " + what + " has a list of negative length");
        }
        if (binary)
          input.check_count(static_cast<std::uint64_t>(length), size_of(property.type),
                            "list items");
        for (std::uint64_t j = 0; j < static_cast<std::uint64_t>(length); ++j) {
          const double item = values.read(property.type, what.c_str());
          if (k != roles.corners) continue;
          if (item < 0 || item > std::numeric_limits<int>::max()) {
            throw Error(input.name() + ": face " + std::to_string(i) + " names vertex " +
                        std::to_string(static_cast<long long>(item)));
          }
          polygon.push_back(static_cast<int>(item));
        }
      }
      if (element.name == "vertex") {
        if (!std::isfinite(point[0]) || !std::isfinite(point[1]) || !std::isfinite(point[2])) {
          throw Error(input.name() + ": vertex " + std::to_string(i) +
                      " has a coordinate that is not finite");
        }
        add_vertex(set, point, input);
        if (roles.has_normal()) attributes->normal(i, normal);
        if (roles.has_color()) attributes->color(i, color);
      }
      add_polygon(set, polygon, input);
    }
  }
  if (std::string padding = values.expect_end(); !padding.empty())
    set.warnings.push_back(std::move(padding));
  check_corners(set, input.name(), 0);
  if (attributes) attributes->finish(set, input.name());
  return set;
}

}  // namespace sculpt::io
