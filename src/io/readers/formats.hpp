// SPDX-License-Identifier: GPL-3.0-or-later
// One reader per input format, each from a Byte_input. All of them bound every count by the
// bytes that can follow it, refuse trailing data, and throw io::Error with one line.
#pragma once

#include "byte_input.hpp"
#include "io/point_reader.hpp"

namespace sculpt::io {

// Appends a vertex within the input's budget on points (io/input_limits.hpp).
inline void add_vertex(Point_set& set, const Point<3>& point, const Byte_input& input) {
  input.check_room_for_point(set.points.size());
  set.points.push_back(point);
}

// What the three numbers after x y z of a text point file are.
enum class Text_columns {
  coordinates,  // nothing: read past (.txt .csv .xy .p2d)
  by_values,    // on six-number lines (.xyz): colours if all are whole levels 0-255, else normals
  normals,      // nx ny nz (.pwn .xyzn)
  colors,       // r g b, levels or fractions (.xyzrgb)
  leica         // Leica's .pts: x y z intensity r g b (levels), or x y z r g b
};

// "x y [z]" per line (.xyz .pwn .pts .txt .csv .xy .p2d); forced_dimension 2 or 3, or 0 for the
// file's own (the column count of its first point line).
Point_set read_text_points(Byte_input& input, int forced_dimension,
                           Text_columns columns = Text_columns::coordinates);
Point_set read_ply(Byte_input& input);  // ascii, binary little and big endian
Point_set read_off(Byte_input& input);  // OFF, COFF, NOFF, CNOFF, STOFF, 4OFF, nOFF (text)
Point_set read_obj(Byte_input& input);  // v and f records; a point cloud of v lines only
Point_set read_stl(Byte_input& input);  // ascii and binary; equal corners merged
Point_set read_las(Byte_input& input);  // LAS 1.0-1.4, uncompressed; X, Y, Z scaled
Point_set read_pcd(Byte_input& input);  // PCD ascii and binary; x, y, z

}  // namespace sculpt::io
