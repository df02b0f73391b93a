// SPDX-License-Identifier: GPL-3.0-or-later
// What the mesh readers share about faces: a polygon becomes a fan of triangles, and once the
// whole file is read every corner must name one of its vertices.
#pragma once

#include <string>
#include <vector>

#include "byte_input.hpp"
#include "io/point_reader.hpp"

namespace sculpt::io {

// The triangles (c0, c[j-1], c[j]) of a polygon; none for fewer than 3 corners.
// Splits a polygon into a fan of triangles, within the input's budget on faces.
void add_polygon(Point_set& set, const std::vector<int>& corners, const Byte_input& input);

// Throws io::Error if a triangle names a vertex the file does not hold; `first_index` is how
// the format counts vertices in messages (0 for PLY, 1 for OBJ).
void check_corners(const Point_set& set, const std::string& name, int first_index);

}  // namespace sculpt::io
