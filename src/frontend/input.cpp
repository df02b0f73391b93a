// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/input.hpp"

#include <algorithm>
#include <chrono>

#include "io/point_reader.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::frontend {

Input load_input(const std::string& path, const std::string& example, int forced_dimension,
                 bool merge_duplicates) {
  Input input;
  if (!example.empty()) {
    const shapes::Example* found = shapes::find_example(example);
    if (!found) {
      std::string names;
      for (const auto& known : shapes::examples())
        names += (names.empty() ? "" : ", ") + known.name;
      throw io::Error("no built-in example named '" + example + "' (examples: " + names + ")");
    }
    input.description = "example " + found->name;
    if (found->dimension == 2) {
      input.points = shapes::example_points_2(found->name);
    } else {
      input.points = shapes::example_points_3(found->name);
    }
    return input;
  }
  const auto start = std::chrono::steady_clock::now();
  io::Point_set set = io::read_points(path);
  input.description = path;
  input.warnings = set.warnings;
  if (merge_duplicates) {
    const std::size_t merged = io::merge_duplicates(set);
    if (merged > 0)
      input.description += " (" + std::to_string(merged) + " duplicate points merged)";
  }
  const int dimension = forced_dimension ? forced_dimension : set.dimension;
  if (dimension == 2) {
    std::string dropped;
    input.points = io::planar_points(set, &dropped);
    if (!dropped.empty()) input.description += " (without its constant " + dropped + ")";
  } else {
    input.points = io::spatial_points(set);
    input.reference_triangles = set.triangles;
    input.attributes = std::move(set.attributes);
  }
  input.read_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return input;
}

Any_reconstruction reconstruct_input(const Input& input, const Options& options) {
  return std::visit(
      [&](const auto& points) -> Any_reconstruction { return reconstruct(points, options); },
      input.points);
}

}  // namespace sculpt::frontend
