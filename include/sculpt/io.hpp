// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// Files through libsculpt, for programs of their own: the command line's readers (every format
/// `sculpt reconstruct` reads, validated and fuzzed) and its writers (every format it writes,
/// all files of a result or none, never over a file read_points read). Errors are
/// sculpt::File_error, an Input_error with one line ready for the user.
#pragma once

#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt {

class File_error : public Input_error {
 public:
  using Input_error::Input_error;
};

/// The points of a point or mesh file.
struct Point_file {
  int dimension = 3;                ///< coordinates per point in the file: 2 or 3
  std::vector<Point<3>> points;     ///< in the file's order; a 2D file's have z = 0
  std::vector<Facet<3>> triangles;  ///< a mesh file's faces, split into triangles; else empty
  Point_attributes attributes;      ///< normals and colours, where a 3D file has them
  std::vector<std::string>
      warnings;  ///< what was read past (padding, a missing endsolid), a line each

  /// The points of a 2D file (or a flat 3D one) in their plane, for reconstruct's curves.
  std::vector<Point<2>> planar() const;
};

/// Reads .xyz .pwn .xyzn .xyzrgb .pts .txt .csv .xy .p2d .ply .off .obj .stl .las .pcd, by the
/// extension, with the points' normals and colours where the file has them.
/// With merge_duplicates, repeated points are dropped (first occurrences kept, in order).
Point_file read_points(const std::string& path, bool merge_duplicates = false);

/// Writes a reconstruction by the extensions: a surface as .stl .ply (binary unless ascii) .off
/// .obj, a curve as .obj .svg, and, if solid_path is given, its solid as .mesh .vtu .node/.ele.
/// Vertex i is sample i. Every destination is checked before anything is written. A surface
/// written as .ply or .obj carries the samples' normals and colours when attributes has them (one
/// per sample each, e.g. a Point_file's; the power crust's own vertices have none).
void write(const Reconstruction<3>& result, const std::string& path,
           const std::string& solid_path = "", bool ascii = false,
           const Point_attributes& attributes = {});
void write(const Reconstruction<2>& result, const std::string& path,
           const std::string& solid_path = "");

}  // namespace sculpt
