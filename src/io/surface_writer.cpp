// 3D surfaces through CGAL's polygon-soup writers.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include "atomic_file.hpp"
#include "point_reader.hpp"
#include "writers.hpp"

namespace sculpt::io {

const char* const surface_formats = ".stl .ply .off .obj";

bool writes_surface(const std::string& extension) {
  return extension == ".stl" || extension == ".ply" || extension == ".off" || extension == ".obj";
}

void write_surface(const std::string& path, const std::vector<Point<3>>& samples,
                   const std::vector<Facet<3>>& triangles, bool ascii) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::string extension = extension_of(path);
  const bool binary = !ascii && (extension == ".stl" || extension == ".ply");
  if (!writes_surface(extension)) {
    throw Error("cannot write a surface as '" + extension + "' (known: " + surface_formats + ")");
  }
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
  const auto precise = CGAL::parameters::stream_precision(17);
  bool written = false;
  if (extension == ".stl") written = CGAL::IO::write_STL(out, points, faces, precise);
  if (extension == ".ply") written = CGAL::IO::write_PLY(out, points, faces, precise);
  if (extension == ".off") written = CGAL::IO::write_OFF(out, points, faces, precise);
  if (extension == ".obj") written = CGAL::IO::write_OBJ(out, points, faces, precise);
  if (!written) throw Error("failed while writing '" + path + "'");
  file.commit();
}

}  // namespace sculpt::io
