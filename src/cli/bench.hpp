// `sculpt bench`: time and memory of every stage next to CGAL's Delaunay triangulation of the
// same points, each measured in a process of its own so that peak memory is the run's own.
#pragma once

#include <string>
#include <vector>

namespace sculpt::cli {

struct Bench_arguments {
  std::vector<std::string> inputs;    // point files
  std::vector<std::string> examples;  // built-in example names
  int torus_points = 0;               // also random points on a torus, if > 0
  int render_triangles = 0;           // also time a headless render of a surface this large
  bool bordered = false;
  bool merge_duplicates = false;
  std::string json;  // write the rows as JSON too
};

int run_bench(const Bench_arguments& args);

}  // namespace sculpt::cli
