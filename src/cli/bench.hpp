// SPDX-License-Identifier: GPL-3.0-or-later
// `sculpt bench`: every method next to CGAL's Delaunay triangulation and CGAL's Advancing Front
// on the same points. Each measurement is a process of its own (`sculpt bench-job`, started
// afresh, not forked), so its CPU time and peak memory are the whole process's, reading the
// input included, as a user would measure `sculpt reconstruct` with /usr/bin/time.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace sculpt::cli {

struct Bench_arguments {
  std::vector<std::string> inputs;           // point files
  std::vector<std::string> examples;         // built-in example names
  std::vector<std::string> loop_subdivided;  // meshes measured once Loop-subdivided (4x denser)
  int torus_points = 0;                      // also random points on a torus, if > 0
  int render_triangles = 0;                  // also time a headless render of a surface this large
  bool edits = false;                // also time the viewer's live 2D edit (200 to 5,000 points)
  int runs = 1;                      // each measurement this many times, interleaved: the median
  std::vector<std::string> methods;  // empty: every method
  bool advancing_front = true;       // also CGAL's Advancing Front (3D)
  bool bordered = false, closed = false;  // neither: each file's kind is chosen from it
  bool merge_duplicates = false;
  std::string cleaning = "auto";  // Options::cleaning by name, for every method measured
  std::string json;               // write the rows as JSON too
};

int run_bench(const Bench_arguments& args);

// The inputs of a benchmark (files, examples, the torus) as names and the arguments that give
// them to a measuring process. Throws Usage_error for an unknown method or example.
std::vector<std::pair<std::string, std::vector<std::string>>> bench_inputs(
    const Bench_arguments& args);

// Throws Usage_error if none of the methods of --methods applies to any input measured (a
// curve method given only surfaces): a table with no method in it. One that applies to some
// inputs is measured on those (the others' rows say it is not for their dimension).
void check_a_method_measured(const std::vector<std::string>& methods,
                             const std::vector<nlohmann::json>& rows);
// One input measured: CGAL's Delaunay triangulation of it ("delaunay_only"), CGAL's Advancing
// Front if asked ("advancing_front") and every method that applies ("methods"), each in a
// process of its own, the median of args.runs runs.
nlohmann::json measure_input(const std::string& name, const std::vector<std::string>& source,
                             const Bench_arguments& args);

// One measurement, in the process `sculpt bench` starts: prints its JSON on standard output
// (bench_jobs.cpp).
struct Bench_job {
  // "delaunay", "method", "advancing-front", "render" (a torus of N triangles) or "edit" (a
  // live 2D edit on N samples)
  std::string job;
  std::string method;
  std::string input, example;
  int torus_points = 0;
  bool bordered = false, closed = false;  // neither: the kind is chosen (Options{}.kind)
  bool merge_duplicates = false;
  std::string cleaning = "auto";  // Options::cleaning by name
};

int run_bench_job(const Bench_job& job);

}  // namespace sculpt::cli
