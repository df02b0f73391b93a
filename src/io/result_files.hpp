// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction written to files: its surface (3D) or curve (2D) by the path's extension,
// and its solid when a path is given, all of them or none, every destination checked before
// anything is written (never over an input). What `sculpt reconstruct`, Python's write() and
// the C++ API's sculpt::write share. Throws io::Error with one line.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "destinations.hpp"
#include "output_set.hpp"
#include "point_reader.hpp"
#include "writers.hpp"

namespace sculpt::io {

// A format some writer knows for each path (the solid's only when given).
template <int D>
void check_result_formats(const std::string& path, const std::string& solid_path) {
  const std::string extension = extension_of(path);
  if (D == 3 ? !writes_surface(extension) : !writes_curve(extension)) {
    throw Error(std::string("cannot write a ") + (D == 3 ? "surface" : "curve") + " as '" + path +
                "' (known: " + (D == 3 ? surface_formats : curve_formats) + ")");
  }
  if (!solid_path.empty() && !writes_solid(extension_of(solid_path))) {
    throw Error("cannot write a solid as '" + solid_path + "' (known: " + solid_formats + ")");
  }
}

// Writes the result's files under the set's temporary names (the set commits them, with any
// other output of the run). Vertex i is sample i, or the result's own vertex i if it does not
// interpolate (the power crust).
template <int D>
void stage_result(Output_set& outputs, const Reconstruction<D>& result, const std::string& path,
                  const std::string& solid_path, bool ascii) {
  const std::vector<Point<D>> samples(result.sites.begin(),
                                      result.sites.begin() + result.sample_count());
  const std::vector<Point<D>>& vertices = result.interpolates() ? samples : result.surface_vertices;
  if constexpr (D == 3) {
    write_surface(outputs.stage(path), vertices, result.surface, ascii);
  } else {
    write_curve(outputs.stage(path), vertices, result.surface);
  }
  if (!solid_path.empty()) write_solid<D>(outputs.stage(solid_path), samples, result.solid);
}

template <int D>
void write_result(const Reconstruction<D>& result, const std::string& path,
                  const std::string& solid_path, bool ascii) {
  check_result_formats<D>(path, solid_path);
  check_destinations(with_companions({path, solid_path}));  // and files read before
  Output_set outputs;
  stage_result(outputs, result, path, solid_path, ascii);
  outputs.commit();
}

}  // namespace sculpt::io
