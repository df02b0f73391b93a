// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction written to files: its surface (3D) or curve (2D) by the path's extension,
// and its solid when a path is given, all of them or none, every destination checked before
// anything is written (never over an input). What `sculpt reconstruct`, Python's write() and
// the C++ API's sculpt::write share. Throws io::Error with one line.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "../core/without.hpp"
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

// The normals and colours of the samples the surface passes through: those given, less the
// outliers' where the cleaning removed some (Reconstruction::removed_outliers) and a list has one
// per sample as given.
template <int D>
Point_attributes attributes_of_samples(const Reconstruction<D>& result,
                                       const Point_attributes& given) {
  const std::vector<int>& removed = result.removed_outliers;
  if (removed.empty()) return given;
  const std::size_t as_given = result.sample_count() + removed.size();
  const auto kept = [&](const auto& values) {
    // A list of another length is left for check_attributes to name.
    return values.size() == as_given ? without(values, removed) : values;
  };
  return {kept(given.normals), kept(given.colors)};
}

// The samples' normals and colours, each list empty or one per sample, for a surface.
template <int D>
void check_attributes(const Reconstruction<D>& result, const Point_attributes& attributes) {
  if (attributes.empty()) return;
  if (D == 2) throw Error("normals and colours are written with surfaces, not with 2D curves");
  const std::size_t samples = result.sample_count();
  for (const auto& [given, what] : {std::pair{attributes.normals.size(), "normals"},
                                    std::pair{attributes.colors.size(), "colours"}}) {
    if (given != 0 && given != samples) {
      throw Error(std::to_string(given) + " " + what + " for " + std::to_string(samples) +
                  " samples: give one per sample, in the samples' order");
    }
  }
}

// Whether the surface file at `path` will hold the samples' normals and colours: its format
// carries them and its vertices are the samples (not the power crust's own).
template <int D>
bool writes_attributes(const Reconstruction<D>& result, const Point_attributes& attributes,
                       const std::string& path) {
  return D == 3 && !attributes.empty() && result.interpolates() &&
         carries_attributes(extension_of(path));
}

// Writes the result's files under the set's temporary names (the set commits them, with any
// other output of the run). Vertex i is sample i, or the result's own vertex i if it does not
// interpolate (the power crust); the samples' attributes go with them (writes_attributes).
template <int D>
void stage_result(Output_set& outputs, const Reconstruction<D>& result, const std::string& path,
                  const std::string& solid_path, bool ascii,
                  const Point_attributes& given_attributes = {}) {
  const Point_attributes attributes = attributes_of_samples(result, given_attributes);
  const std::vector<Point<D>> samples(result.sites.begin(),
                                      result.sites.begin() + result.sample_count());
  const std::vector<Point<D>>& vertices = result.interpolates() ? samples : result.surface_vertices;
  if constexpr (D == 3) {
    write_surface(outputs.stage(path), vertices, result.surface, ascii,
                  writes_attributes(result, attributes, path) ? attributes : Point_attributes{});
  } else {
    write_curve(outputs.stage(path), vertices, result.surface);
  }
  if (!solid_path.empty()) write_solid<D>(outputs.stage(solid_path), samples, result.solid);
}

template <int D>
void write_result(const Reconstruction<D>& result, const std::string& path,
                  const std::string& solid_path, bool ascii,
                  const Point_attributes& attributes = {}) {
  check_result_formats<D>(path, solid_path);
  check_attributes(result, attributes_of_samples(result, attributes));
  check_destinations(with_companions({path, solid_path}));  // and files read before
  Output_set outputs;
  stage_result(outputs, result, path, solid_path, ascii, attributes);
  outputs.commit();
}

}  // namespace sculpt::io
