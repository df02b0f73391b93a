// SPDX-License-Identifier: GPL-3.0-or-later
// Where the samples of a command or the viewer come from: a point file or a built-in example, in
// the dimension the file gives or the user forces.
#pragma once

#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <string>
#include <variant>
#include <vector>

namespace sculpt::frontend {

struct Input {
  std::string description;  // the file name or "example NAME", and what was done to it
  std::variant<std::vector<Point<2>>, std::vector<Point<3>>> points;
  double read_seconds = 0;
  // A 3D mesh file's own triangles, on the same vertex indices: what a reconstruction of its
  // vertices can be compared with. Empty for point files and examples.
  std::vector<Facet<3>> reference_triangles;
  // The samples' normals and colours where a 3D file has them (empty for 2D and examples).
  Point_attributes attributes;
  // What the reader read past (io::Point_set::warnings), for the front end to say.
  std::vector<std::string> warnings;

  int dimension() const { return points.index() == 0 ? 2 : 3; }
};

// Throws io::Error with a one-line message.
// With merge_duplicates, repeated points of a file are removed (first occurrences kept, in order).
Input load_input(const std::string& path, const std::string& example, int forced_dimension,
                 bool merge_duplicates = false);

// A reconstruction of either dimension, as an input's points make it.
using Any_reconstruction = std::variant<Reconstruction<2>, Reconstruction<3>>;

// An input's points reconstructed, in their dimension.
Any_reconstruction reconstruct_input(const Input& input, const Options& options);

}  // namespace sculpt::frontend
