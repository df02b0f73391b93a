// SPDX-License-Identifier: GPL-3.0-or-later
// Reading samples: the vertices of a point or mesh file, whatever its format.
//   text:   .xyz .pwn .xyzn .xyzrgb .pts .txt .xy .p2d .csv  ("x y [z]" per line; `#` comments,
//           a leading word such as `p` or `v`, a count header, commas and extra columns)
//   meshes: .ply (ascii or binary, any scalar type) .off (and COFF, NOFF, STOFF, 4OFF, nOFF)
//           .obj (a point cloud of `v` lines too) .stl (ascii or binary)
// Normals and colours are kept from PLY (nx ny nz, red green blue), OBJ (`vn` one per vertex,
// `v x y z r g b`), .pwn .xyzn and 6-column .xyz (x y z nx ny nz), .xyzrgb (x y z r g b) and
// .pts (Leica's x y z intensity r g b, or x y z r g b).
//   scans:  .las (LAS 1.0-1.4, uncompressed) .pcd (PCL's, ascii or binary)
// The readers are Sculpt's own (src/io/readers), written to survive any bytes: every count is
// checked against the bytes that can follow it, files are streamed, and all are fuzzed.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "input_limits.hpp"
#include "io_error.hpp"

namespace sculpt::io {

struct Point_set {
  std::vector<Point<3>> points;  // 2D files have z = 0
  int dimension = 3;             // coordinates per point in the file: 2 or 3
  // A mesh file's faces, as triangles (polygons split into fans): the reference a
  // reconstruction of its vertices is compared with (sculpt bench, the tests). Empty otherwise.
  std::vector<std::array<int, 3>> triangles;
  // Normals and colours, each for every point or none (2D files have none).
  Point_attributes attributes;
  // What was read past and how (padding after a PLY's last element, an STL without endsolid):
  // one line each, for the front end to show as a warning.
  std::vector<std::string> warnings;
};

// The extensions read_points knows, for messages and --help.
extern const char* const point_formats;

// Throws io::Error with a one-line message on any problem with the file, and for a file or a
// stream that holds more bytes or points than the limits (io/input_limits.hpp).
Point_set read_points(const std::string& path, const Input_limits& limits = input_limits());
// The same readers on bytes in memory; `extension` (".ply", ".xyz", ...) names the format.
// A chunk size hands the bytes over that many at a time, as a pipe would (fuzzing, tests).
Point_set read_points_from_memory(std::string_view bytes, const std::string& extension,
                                  std::size_t chunk = 0);

// The points of a set in a plane: a 2D file's (x, y), or a 3D set whose points all share one
// coordinate, without it (`dropped` names it: "x", "y" or "z"). Throws io::Error otherwise.
std::vector<Point<2>> planar_points(const Point_set& set, std::string* dropped = nullptr);

std::vector<Point<3>> spatial_points(const Point_set& set);

// Removes repeated points (exact copies), keeping each first occurrence in order; returns how
// many were removed. Scans often hold a few; reconstruction refuses them otherwise.
std::size_t merge_duplicates(Point_set& set);

// Which points repeat an earlier one exactly (the rule of merge_duplicates); `order`, if given,
// receives the indices sorted by point, equal points in input order.
template <class Point>
std::vector<bool> repeated_points(const std::vector<Point>& points,
                                  std::vector<std::size_t>* order = nullptr) {
  std::vector<std::size_t> sorted(points.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = i;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
  std::vector<bool> repeated(points.size(), false);
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    repeated[sorted[k]] = points[sorted[k]] == points[sorted[k - 1]];
  }
  if (order) *order = std::move(sorted);
  return repeated;
}

// The extension of a path in lower case, with its dot ("" if none).
std::string extension_of(const std::string& path);

}  // namespace sculpt::io
