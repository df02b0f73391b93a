// SPDX-License-Identifier: GPL-3.0-or-later
// A surface as PLY (Turk 1994): its vertices as doubles with their normals (doubles) and colours
// (uchar red green blue) when the samples have them, and its triangles, in binary (the host's
// byte order, which the header names) or in text with every number in its shortest exact form.
#pragma once

#include <ostream>
#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt::io {

void write_ply(std::ostream& out, const std::vector<Point<3>>& vertices,
               const std::vector<Facet<3>>& triangles, const Point_attributes& attributes,
               bool binary);

}  // namespace sculpt::io
