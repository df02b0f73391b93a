// SPDX-License-Identifier: GPL-3.0-or-later
// STL: a soup of triangles, in binary (an 80-byte header, a triangle count, 50 bytes per
// triangle) or ASCII (`solid`, then `facet ... outer loop, vertex x y z ..., endloop endfacet`).
// Corners at equal positions are one vertex, numbered in order of first appearance.
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "formats.hpp"
#include "io/io_error.hpp"
#include "text_lines.hpp"
#include "words.hpp"

namespace sculpt::io {
namespace {

// Numbers the distinct corners of a triangle soup.
class Vertex_numbering {
 public:
  Vertex_numbering(Point_set& set, const Byte_input& input) : set_(set), input_(input) {}

  int number(Point<3> p) {
    for (double& x : p) x = x == 0 ? 0 : x;  // -0 and 0 are one position
    const auto found = numbers_.find(p);
    if (found != numbers_.end()) return found->second;
    const int number = static_cast<int>(set_.points.size());
    add_vertex(set_, p, input_);
    numbers_.emplace(p, number);
    return number;
  }

 private:
  struct Hash {
    std::size_t operator()(const Point<3>& p) const {
      std::size_t h = 0;
      for (double x : p) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ull + (h >> 29);
      }
      return h;
    }
  };
  Point_set& set_;
  const Byte_input& input_;
  std::unordered_map<Point<3>, int, Hash> numbers_;
};

void add_triangle(Point_set& set, const int corners[3], const Byte_input& input) {
  if (corners[0] != corners[1] && corners[1] != corners[2] && corners[0] != corners[2]) {
    input.check_room_for_face(set.triangles.size());
    set.triangles.push_back({corners[0], corners[1], corners[2]});
  }
}

Point<3> checked(const float coordinates[3], const std::string& where) {
  Point<3> p{coordinates[0], coordinates[1], coordinates[2]};
  for (double x : p) {
    if (!std::isfinite(x)) throw Error(where + ": a corner has a coordinate that is not finite");
  }
  return p;
}

Point_set read_binary_stl(Byte_input& input) {
  char header[80];
  input.read(header, 80, "the 80-byte STL header");
  unsigned char count_bytes[4];
  input.read(count_bytes, 4, "the STL triangle count");
  const std::uint64_t count = std::uint64_t(count_bytes[0]) | std::uint64_t(count_bytes[1]) << 8 |
                              std::uint64_t(count_bytes[2]) << 16 |
                              std::uint64_t(count_bytes[3]) << 24;
  input.check_count(count, 50, "triangles of 50 bytes");
  Point_set set;
  set.dimension = 3;
  Vertex_numbering numbering(set, input);
  for (std::uint64_t t = 0; t < count; ++t) {
    unsigned char record[50];
    input.read(record, 50, "an STL triangle");
    float values[12];
    for (int k = 0; k < 12; ++k) {  // little endian IEEE floats: the normal, then the corners
      const unsigned char* b = record + 4 * k;
      const std::uint32_t bits = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 |
                                 std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
      std::memcpy(&values[k], &bits, sizeof bits);
    }
    const std::string where = input.name() + " triangle " + std::to_string(t);
    int corners[3];
    for (int c = 0; c < 3; ++c) corners[c] = numbering.number(checked(values + 3 + 3 * c, where));
    add_triangle(set, corners, input);
  }
  if (!input.at_end()) {
    throw Error(input.name() + ": data after the " + std::to_string(count) +
                " triangles its header announces (at byte " + std::to_string(input.offset()) + ")");
  }
  return set;
}

Point_set read_ascii_stl(Byte_input& input) {
  Text_lines lines(input, "an ASCII STL file");
  std::vector<std::string_view> words;
  Point_set set;
  set.dimension = 3;
  Vertex_numbering numbering(set, input);
  enum class State { outside, in_solid, in_facet, in_loop } state = State::outside;
  std::vector<int> loop;
  auto refuse = [&](const std::string& what) { throw Error(lines.where() + ": " + what); };
  while (lines.next(words, 0)) {
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (state == State::outside) {
      if (!same_word(keyword, "solid")) refuse("expected 'solid'");
      state = State::in_solid;
    } else if (state == State::in_solid) {
      if (same_word(keyword, "endsolid")) {
        state = State::outside;
      } else if (same_word(keyword, "facet")) {
        state = State::in_facet;
      } else {
        refuse("expected 'facet' or 'endsolid'");
      }
    } else if (state == State::in_facet) {
      if (same_word(keyword, "outer") && words.size() == 2 && same_word(words[1], "loop")) {
        state = State::in_loop;
        loop.clear();
      } else if (same_word(keyword, "endfacet")) {
        state = State::in_solid;
      } else {
        refuse("expected 'outer loop' or 'endfacet'");
      }
    } else if (same_word(keyword, "vertex")) {
      if (words.size() != 4) refuse("expected 'vertex x y z'");
      Point<3> p{0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        if (!parse_number(words[k + 1], p[k])) {
          refuse("'" + printable(words[k + 1]) + "' is not a number");
        }
      }
      for (double x : p) {
        if (!std::isfinite(x)) refuse("a coordinate is not finite");
      }
      loop.push_back(numbering.number(p));
    } else if (same_word(keyword, "endloop")) {
      if (loop.size() < 3) refuse("a facet with fewer than 3 vertices");
      for (std::size_t j = 2; j < loop.size(); ++j) {
        const int corners[3] = {loop[0], loop[j - 1], loop[j]};
        add_triangle(set, corners, input);
      }
      state = State::in_facet;
    } else {
      refuse("expected 'vertex' or 'endloop'");
    }
  }
  if (state == State::in_solid) {
    // Every facet is whole; only the closing keyword is missing, as some exporters write it.
    set.warnings.push_back(input.name() +
                           " ends without 'endsolid' after its last facet; read "
                           "as complete");
  } else if (state != State::outside) {
    throw Error(input.name() + " is truncated: it ends inside a facet");
  }
  return set;
}

}  // namespace

Point_set read_stl(Byte_input& input) {
  input.skip_byte_order_mark();  // before an ASCII "solid"
  // An ASCII file starts with "solid" and is text; a binary header may start with "solid" too,
  // but then its size is exactly 84 + 50 per triangle, or it holds binary bytes early on.
  const std::string head(input.peek(84));  // a copy: the next peek may move the buffer
  bool ascii = false;
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start != std::string_view::npos &&
      same_word(std::string_view(head).substr(start, 5), "solid") &&
      !looks_binary(input.peek(512))) {
    ascii = true;
    if (head.size() == 84) {
      std::uint64_t count = 0;
      for (int k = 3; k >= 0; --k) count = count << 8 | static_cast<unsigned char>(head[80 + k]);
      if (input.remaining_bound() == 84 + 50 * count && input.remaining_bound() != 0) ascii = false;
    }
  }
  return ascii ? read_ascii_stl(input) : read_binary_stl(input);
}

}  // namespace sculpt::io
