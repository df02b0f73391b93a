// SPDX-License-Identifier: GPL-3.0-or-later
// `sculpt compare`: the methods side by side on the same inputs, as the paper argues (Kuo & Yau
// sec. 7, Table 2) and a course needs: one table (markdown on standard output, and JSON) of the
// time and memory of each method against CGAL's Delaunay triangulation of the same points
// (sculpt bench's measurements, each a process of its own), what each result is (the verdict and
// its counts), and, against a reference mesh, the share of its triangles reproduced and the
// two-sided Hausdorff distance; and a picture grid, inputs by methods, each input under one camera.
#pragma once

#include <string>

#include "bench.hpp"

namespace sculpt::cli {

struct Compare_arguments {
  Bench_arguments inputs;  // files, examples, methods, runs, merge_duplicates, bordered
  std::string reference;   // a mesh the (one) input is measured against; a mesh input is its own
  std::string markdown, json, pictures;
  std::string tile = "320x320";  // one picture of the grid
};

int run_compare(const Compare_arguments& args);

}  // namespace sculpt::cli
