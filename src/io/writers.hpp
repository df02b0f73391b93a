// SPDX-License-Identifier: GPL-3.0-or-later
// Writing results. Every writer chooses the format by the path's extension, writes the file
// completely or not at all, and throws io::Error with a one-line message.
//   surface (3D triangles): .stl (binary unless ascii), .ply (binary unless ascii), .off, .obj;
//                           PLY and OBJ with the samples' normals and colours when given
//   curve (2D edges):       .obj (polylines as `l` elements), .svg
//   solid (tetrahedra or triangles): .mesh (Medit), .vtu (ParaView), .node/.ele (TetGen, Triangle)
// Vertices are all the samples, in input order, so vertex i of the output is sample i.
#pragma once

#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "io_error.hpp"

namespace sculpt::io {

// Attributes are written where the format carries them (carries_attributes) and when they
// are given for every vertex.
void write_surface(const std::string& path, const std::vector<Point<3>>& samples,
                   const std::vector<Facet<3>>& triangles, bool ascii,
                   const Point_attributes& attributes = {});

void write_curve(const std::string& path, const std::vector<Point<2>>& samples,
                 const std::vector<Facet<2>>& edges);

// Writes only the samples as vertices (solid cells have no other vertices).
template <int D>
void write_solid(const std::string& path, const std::vector<Point<D>>& samples,
                 const std::vector<Cell<D>>& cells);

// Whether a writer knows the extension (lower case, with its dot: see extension_of).
bool writes_surface(const std::string& extension);
bool writes_curve(const std::string& extension);
bool writes_solid(const std::string& extension);
// Whether a surface format has per-vertex normals and colours: .ply and .obj.
bool carries_attributes(const std::string& extension);

// The formats each writer knows, for messages and --help.
extern const char* const surface_formats;
extern const char* const curve_formats;
extern const char* const solid_formats;

}  // namespace sculpt::io
