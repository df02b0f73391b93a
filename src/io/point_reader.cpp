// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_reader.hpp"

#include <algorithm>
#include <cctype>

#include "readers/formats.hpp"
#include "readers/words.hpp"

namespace sculpt::io {

const char* const point_formats =
    ".xyz .pwn .xyzn .xyzrgb .pts .txt .csv .xy .p2d .ply .off .obj .stl .las .pcd";

namespace {

Point_set read_format(Byte_input& input, const std::string& extension) {
  Point_set set;
  if (extension == ".off") {
    set = read_off(input);
  } else if (extension == ".obj") {
    set = read_obj(input);
  } else if (extension == ".ply") {
    set = read_ply(input);
  } else if (extension == ".stl") {
    set = read_stl(input);
  } else if (extension == ".las") {
    set = read_las(input);
  } else if (extension == ".pcd") {
    set = read_pcd(input);
  } else if (extension == ".xy" || extension == ".p2d") {
    set = read_text_points(input, 2);
  } else if (extension == ".pwn" || extension == ".xyzn") {  // CGAL's, Open3D's: x y z nx ny nz
    set = read_text_points(input, 3, Text_columns::normals);
  } else if (extension == ".xyzrgb") {  // Open3D's: x y z r g b
    set = read_text_points(input, 3, Text_columns::colors);
  } else if (extension == ".xyz") {
    set = read_text_points(input, 3, Text_columns::by_values);
  } else if (extension == ".pts") {
    set = read_text_points(input, 0, Text_columns::leica);
  } else {
    set = read_text_points(input, 0);
  }
  if (set.points.empty()) throw Error(input.name() + " holds no points");
  return set;
}

bool known_extension(const std::string& extension) {
  for (const char* known : {".off", ".obj", ".ply", ".stl", ".las", ".pcd", ".xy", ".p2d", ".xyz",
                            ".pwn", ".xyzn", ".xyzrgb", ".pts", ".txt", ".csv", ""}) {
    if (extension == known) return true;
  }
  return false;
}

}  // namespace

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

Point_set read_points(const std::string& path, const Input_limits& limits) {
  const std::string extension = extension_of(path);
  if (extension == ".laz" || extension == ".e57") {
    // Both need a decoder that Debian does not package (LASzip, libE57Format).
    throw Error("'" + printable(path, 1000) + "' is " +
                (extension == ".laz" ? std::string("compressed LAS (LAZ)") : std::string("E57")) +
                ", which Sculpt cannot read: no Debian package decodes it; convert it to .ply "
                "first (e.g. PDAL or CloudCompare)");
  }
  if (!known_extension(extension)) {
    throw Error("unknown point format '" + printable(extension) + "' of '" + printable(path, 1000) +
                "' (known: " + std::string(point_formats) + ")");
  }
  Byte_input input = Byte_input::open_file(path, limits);
  return read_format(input, extension);
}

Point_set read_points_from_memory(std::string_view bytes, const std::string& extension,
                                  std::size_t chunk) {
  Byte_input input = Byte_input::from_memory(bytes, "'input" + extension + "'", chunk);
  return read_format(input, extension);
}

std::vector<Point<2>> planar_points(const Point_set& set, std::string* dropped) {
  int drop = 2;
  if (set.dimension == 3) {
    std::vector<int> constant;
    for (int k = 0; k < 3; ++k) {
      const bool same = std::all_of(set.points.begin(), set.points.end(),
                                    [&](const Point<3>& p) { return p[k] == set.points[0][k]; });
      if (same) constant.push_back(k);
    }
    if (constant.empty()) {
      throw Error(
          "the points are not in a coordinate plane: no coordinate is the same for all "
          "of them, so they cannot be read as 2D");
    }
    drop = constant.back();
  }
  if (dropped) *dropped = set.dimension == 3 ? std::string(1, "xyz"[drop]) : "";
  std::vector<Point<2>> points;
  points.reserve(set.points.size());
  for (const auto& p : set.points) {
    Point<2> q;
    for (int k = 0, j = 0; k < 3; ++k) {
      if (k != drop) q[j++] = p[k];
    }
    points.push_back(q);
  }
  return points;
}

std::size_t merge_duplicates(Point_set& set) {
  std::vector<std::size_t> order;
  const std::vector<bool> repeated = repeated_points(set.points, &order);
  std::vector<Point<3>> kept;
  kept.reserve(set.points.size());
  std::vector<int> new_index(set.points.size());
  Point_attributes& attributes = set.attributes;
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    if (!repeated[i]) {
      // A copy's normal and colour go with it: the first occurrence's are kept.
      if (!attributes.normals.empty()) attributes.normals[kept.size()] = attributes.normals[i];
      if (!attributes.colors.empty()) attributes.colors[kept.size()] = attributes.colors[i];
      new_index[i] = static_cast<int>(kept.size());
      kept.push_back(set.points[i]);
    }
  }
  if (!attributes.normals.empty()) attributes.normals.resize(kept.size());
  if (!attributes.colors.empty()) attributes.colors.resize(kept.size());
  for (std::size_t k = 1; k < order.size(); ++k) {  // a copy takes its first occurrence's index
    if (repeated[order[k]]) new_index[order[k]] = new_index[order[k - 1]];
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto t : set.triangles) {
    for (int& v : t) v = new_index[v];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  set.triangles = std::move(triangles);
  const std::size_t merged = set.points.size() - kept.size();
  set.points = std::move(kept);
  return merged;
}

std::vector<Point<3>> spatial_points(const Point_set& set) {
  if (set.dimension == 2) {
    throw Error("the file gives 2 coordinates per point: a surface needs 3 (or use --dim 2)");
  }
  return set.points;
}

}  // namespace sculpt::io
