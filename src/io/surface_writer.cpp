// SPDX-License-Identifier: GPL-3.0-or-later
// 3D surfaces: STL through CGAL's polygon-soup writer; PLY (io/ply_writer.hpp), OFF and OBJ
// written here with fmt, each coordinate in the shortest form that reads back as the same double.
// PLY and OBJ carry the samples' normals and colours.
// (CGAL's text writers print 17 digits through iostreams: 0.04 s for bunny00's 75k triangles, 7%
// of the whole run; this takes a tenth of that.)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "atomic_file.hpp"
#include "output_buffer.hpp"
#include "ply_writer.hpp"
#include "point_reader.hpp"
#include "temporary_files.hpp"
#include "writers.hpp"

namespace sculpt::io {

const char* const surface_formats = ".stl .ply .off .obj";

bool writes_surface(const std::string& extension) {
  return extension == ".stl" || extension == ".ply" || extension == ".off" || extension == ".obj";
}

bool carries_attributes(const std::string& extension) {
  return extension == ".ply" || extension == ".obj";
}

namespace {

void write_off(std::ostream& out, const std::vector<Point<3>>& samples,
               const std::vector<Facet<3>>& triangles) {
  Output_buffer text(out);
  text.line("OFF");
  text.line("{} {} 0", samples.size(), triangles.size());
  for (const auto& p : samples) text.line("{} {} {}", p[0], p[1], p[2]);
  for (const auto& t : triangles) text.line("3 {} {} {}", t[0], t[1], t[2]);
}

// Normals as `vn` lines, one per vertex and named by each face corner (`f a//a ...`); colours
// as fractions after a vertex's coordinates (`v x y z r g b`, as MeshLab and Open3D write them).
void write_obj(std::ostream& out, const std::vector<Point<3>>& samples,
               const std::vector<Facet<3>>& triangles, const Point_attributes& attributes) {
  const bool normals = attributes.normals.size() == samples.size() && !samples.empty();
  const bool colors = attributes.colors.size() == samples.size() && !samples.empty();
  Output_buffer text(out);
  text.line("# sculpt: {} vertices, {} triangles", samples.size(), triangles.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& p = samples[i];
    if (colors) {
      const auto& c = attributes.colors[i];
      text.line("v {} {} {} {} {} {}", p[0], p[1], p[2], c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    } else {
      text.line("v {} {} {}", p[0], p[1], p[2]);
    }
  }
  if (normals) {
    for (const auto& n : attributes.normals) text.line("vn {} {} {}", n[0], n[1], n[2]);
  }
  for (const auto& t : triangles) {
    if (normals) {
      text.line("f {0}//{0} {1}//{1} {2}//{2}", t[0] + 1, t[1] + 1, t[2] + 1);
    } else {
      text.line("f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
  }
}

// STL holds what OFF, PLY and OBJ need not: binary STL its coordinates as 32-bit floats, and
// every STL a normal per facet, computed in doubles. Where these coordinates cannot survive that,
// the file would be another surface, so none is written:
//   - binary: a coordinate beyond a float's range, or more than 1% of the triangles collapsed or
//     turned over by rounding to floats (a part far from the origin, as survey coordinates are: a
//     unit sphere at 1e8, where floats are 8 apart, collapses onto a line). Rounding that moves
//     vertices, or turns over a sliver here and there, is STL's own, as it always was (CGAL's
//     rotor_small: 1 sliver of 4,511; ALSTOM_TEST4: edges of 0.001 near 384, moved by 1%);
//   - any STL: a facet normal that overflows or underflows in doubles, its squared length out of
//     range (coordinates beyond about 1e+-77: `nan` normals). A triangle without area at ordinary
//     coordinates is the surface's, not the format's, and is left to the writer.
void check_stl_holds(const std::string& path, const std::vector<Point<3>>& samples,
                     const std::vector<Facet<3>>& triangles, bool binary) {
  const auto refuse = [&](const std::string& why) {
    throw Error("cannot write '" + destination_of(path) + "' as STL: " + why +
                "; write .off, .ply or .obj, which keep every coordinate exactly");
  };
  using Vector = std::array<double, 3>;
  const auto cross = [](const Vector& u, const Vector& v) {
    return Vector{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  const auto dot = [](const Vector& u, const Vector& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  // The triangle's normal (unnormalised), and the same with its edges scaled to at most 1: the
  // direction, whatever the coordinates' size.
  const auto normals = [&](const Point<3>& a, const Point<3>& b, const Point<3>& c) {
    Vector u, v;
    double scale = 0;
    for (int k = 0; k < 3; ++k) {
      u[k] = b[k] - a[k], v[k] = c[k] - a[k];
      scale = std::max({scale, std::abs(u[k]), std::abs(v[k])});
    }
    const Vector n = cross(u, v);
    if (!(scale > 0) || !std::isfinite(scale)) return std::pair<Vector, Vector>{n, Vector{}};
    for (int k = 0; k < 3; ++k) u[k] /= scale, v[k] /= scale;
    return std::pair<Vector, Vector>{n, cross(u, v)};
  };
  std::size_t collapsed = 0;
  for (const auto& t : triangles) {
    const Point<3>&a = samples[t[0]], &b = samples[t[1]], &c = samples[t[2]];
    const auto [n, direction] = normals(a, b, c);
    const double length2 = dot(n, n);
    if (dot(direction, direction) > 0 && (!std::isfinite(length2) || !(length2 > 0))) {
      refuse(
          fmt::format("a facet's normal overflows or underflows at these coordinates ({}, "
                      "{}, {})",
                      a[0], a[1], a[2]));
    }
    if (!binary) continue;
    Point<3> rounded[3];
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        const double x = samples[t[j]][k];
        rounded[j][k] = static_cast<float>(x);
        if (!std::isfinite(rounded[j][k])) {
          refuse(fmt::format("binary STL holds 32-bit floats, which cannot hold {}", x));
        }
      }
    }
    const Vector stored = normals(rounded[0], rounded[1], rounded[2]).second;
    collapsed += dot(direction, direction) > 0 && !(dot(stored, direction) > 0);
  }
  if (collapsed > triangles.size() / 100) {
    refuse(fmt::format(
        "binary STL holds 32-bit floats, which would collapse or turn over {} of its {} "
        "triangles at these coordinates (text STL keeps doubles; or move the part near the "
        "origin)",
        collapsed, triangles.size()));
  }
}

}  // namespace

void write_surface(const std::string& path, const std::vector<Point<3>>& samples,
                   const std::vector<Facet<3>>& triangles, bool ascii,
                   const Point_attributes& attributes) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::string extension = extension_of(path);
  const bool binary = !ascii && (extension == ".stl" || extension == ".ply");
  if (!writes_surface(extension)) {
    throw Error("cannot write a surface as '" + extension + "' (known: " + surface_formats + ")");
  }
  if (extension != ".stl") {
    Atomic_file file(path, binary);
    if (extension == ".ply") write_ply(file.stream(), samples, triangles, attributes, binary);
    if (extension == ".off") write_off(file.stream(), samples, triangles);
    if (extension == ".obj") write_obj(file.stream(), samples, triangles, attributes);
    file.commit();
    return;
  }
  check_stl_holds(path, samples, triangles, binary);
  std::vector<Kernel::Point_3> points;
  points.reserve(samples.size());
  for (const auto& p : samples) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(triangles.size());
  for (const auto& t : triangles)
    faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});

  Atomic_file file(path, binary);
  auto& out = file.stream();
  CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  const bool written =
      CGAL::IO::write_STL(out, points, faces, CGAL::parameters::stream_precision(17));
  // A stream that failed (a full disk, a file-size limit) is reported by commit(), with why.
  if (!written && out) throw Error("failed while writing '" + destination_of(path) + "'");
  file.commit();
}

}  // namespace sculpt::io
