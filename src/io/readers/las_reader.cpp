// SPDX-License-Identifier: GPL-3.0-or-later
// LAS 1.0-1.4, uncompressed (ASPRS LAS specification 1.4 R15): a public header block, variable
// length records, then fixed-size point records whose first twelve bytes are X, Y, Z as 32-bit
// integers, scaled and offset by the header's factors. Every field the points depend on is
// checked: the signature, the version, the header's size for its version, the point format and
// its record length, the count against the bytes that follow, finite non-zero scales. The
// formats with colour (2, 3, 5, 7, 8, 10) give red, green and blue as 16-bit levels.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "attribute_collector.hpp"
#include "core/point_names.hpp"
#include "formats.hpp"
#include "io/io_error.hpp"

namespace sculpt::io {
namespace {

std::uint64_t little_endian(const unsigned char* bytes, int size) {
  std::uint64_t value = 0;
  for (int k = size - 1; k >= 0; --k) value = value << 8 | bytes[k];
  return value;
}

double little_endian_double(const unsigned char* bytes) {
  const std::uint64_t bits = little_endian(bytes, 8);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::int32_t little_endian_int32(const unsigned char* bytes) {
  const auto bits = static_cast<std::uint32_t>(little_endian(bytes, 4));
  std::int32_t value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// The shortest record of each point data format, 0 to 10 (the specification's table).
constexpr int shortest_record[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

// Where a record's red, green and blue start, by point data format; -1 for none.
constexpr int color_offset[] = {-1, -1, 20, 28, -1, 28, -1, 30, 30, -1, 30};

// Consumes `count` bytes without keeping them (the variable length records).
void skip(Byte_input& input, std::uint64_t count, const char* what) {
  char buffer[4096];
  while (count > 0) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(count, sizeof buffer));
    input.read(buffer, n, what);
    count -= n;
  }
}

}  // namespace

Point_set read_las(Byte_input& input) {
  // The fixed part of the public header block: 227 bytes in 1.0-1.2, 235 in 1.3, 375 in 1.4.
  unsigned char header[375] = {};
  input.read(header, 227, "the LAS header");
  if (std::memcmp(header, "LASF", 4) != 0) {
    throw Error(input.name() + " is not a LAS file (it does not start with 'LASF')");
  }
  const int major = header[24], minor = header[25];
  if (major != 1 || minor > 4) {
    throw Error(input.name() + ": LAS version " + std::to_string(major) + "." +
                std::to_string(minor) + " is not one Sculpt reads (1.0 to 1.4)");
  }
  const std::uint64_t fixed = minor == 4 ? 375 : minor == 3 ? 235 : 227;
  if (fixed > 227) input.read(header + 227, fixed - 227, "the LAS header");
  const std::uint64_t header_size = little_endian(header + 94, 2);
  const std::uint64_t point_offset = little_endian(header + 96, 4);
  const int format = header[104];
  const std::uint64_t record = little_endian(header + 105, 2);
  if (header_size < fixed || point_offset < header_size) {
    throw Error(input.name() + " is malformed: a header of " + std::to_string(header_size) +
                " bytes with its points at byte " + std::to_string(point_offset) + " (LAS 1." +
                std::to_string(minor) + " needs at least " + std::to_string(fixed) + ")");
  }
  if (format & 0xC0) {  // LASzip marks its compressed records by these bits
    throw Error(input.name() +
                " holds compressed (LAZ) points, which Sculpt cannot read: no Debian package "
                "decodes them; convert it to .ply or uncompressed .las first");
  }
  if (format > 10) {
    throw Error(input.name() + ": point data format " + std::to_string(format) +
                " is not one of LAS's (0 to 10)");
  }
  if (record < static_cast<std::uint64_t>(shortest_record[format])) {
    throw Error(input.name() + ": records of " + std::to_string(record) +
                " bytes are too short for point data format " + std::to_string(format) + " (" +
                std::to_string(shortest_record[format]) + " bytes at least)");
  }
  // LAS 1.4 keeps the count in 64 bits; the legacy 32-bit field is 0 for large files.
  const std::uint64_t count = minor == 4 && little_endian(header + 107, 4) == 0
                                  ? little_endian(header + 247, 8)
                                  : little_endian(header + 107, 4);
  double scale[3], offset[3];
  for (int k = 0; k < 3; ++k) {
    scale[k] = little_endian_double(header + 131 + 8 * k);
    offset[k] = little_endian_double(header + 155 + 8 * k);
    if (!std::isfinite(scale[k]) || scale[k] == 0 || !std::isfinite(offset[k])) {
      throw Error(input.name() + ": the header's scale and offset must be finite, the scale not 0");
    }
  }
  skip(input, point_offset - fixed, "the LAS variable length records");
  input.check_count(count, record, "LAS point records of " + std::to_string(record) + " bytes");

  Point_set set;
  set.dimension = 3;
  std::vector<unsigned char> bytes(record);
  std::vector<std::array<double, 3>> colors;
  double brightest = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    input.read(bytes.data(), record, "a LAS point record");
    Point<3> point;
    for (int k = 0; k < 3; ++k) {
      point[k] = little_endian_int32(bytes.data() + 4 * k) * scale[k] + offset[k];
      if (!std::isfinite(point[k])) {
        throw Error(input.name() + ": " + ordinal_point(i) +
                    " has a coordinate that is not finite");
      }
    }
    add_vertex(set, point, input);
    if (const int at = color_offset[format]; at >= 0) {
      std::array<double, 3> rgb;
      for (int k = 0; k < 3; ++k) {
        rgb[k] = static_cast<double>(little_endian(bytes.data() + at + 2 * k, 2));
        brightest = std::max(brightest, rgb[k]);
      }
      colors.push_back(rgb);
    }
  }
  // The specification scales colours to 16 bits; many writers store bytes in those fields. No
  // level above 255 means bytes (as PDAL and CloudCompare read them). A format with colour
  // whose colours are all 0 was written without any: none kept.
  Attribute_collector attributes(brightest > 255 ? 65535 : 255);
  if (brightest > 0) {
    for (std::size_t i = 0; i < colors.size(); ++i) attributes.color(i, colors[i]);
  }
  attributes.finish(set, input.name());
  // What follows the points in 1.3 and 1.4 (waveform data, extended variable length records)
  // holds no point. In 1.0-1.2 nothing should follow; writers that pad are read past, as other
  // LAS readers do, with a warning.
  if (minor < 3 && !input.at_end()) {
    set.warnings.push_back(input.name() + ": data after the " + std::to_string(count) +
                           " points its header announces (at byte " +
                           std::to_string(input.offset()) + "), ignored");
  }
  return set;
}

}  // namespace sculpt::io
