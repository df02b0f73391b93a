// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "bench_process.hpp"
#include "bench_tables.hpp"
#include "frontend/command_line.hpp"
#include "frontend/input.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {

void check_a_method_measured(const std::vector<std::string>& methods,
                             const std::vector<nlohmann::json>& rows) {
  const bool any = std::any_of(rows.begin(), rows.end(),
                               [](const nlohmann::json& row) { return !row["methods"].empty(); });
  if (any || rows.empty()) return;
  std::string why;
  for (const auto& name : methods) {
    Method method;
    if (!parse_method(name, method)) continue;
    const bool curves = reconstructs_in(method, 2);
    why += (why.empty() ? "" : "; ") + name + " reconstructs " +
           (curves ? "curves (2D points) only" : "surfaces (3D points) only");
  }
  throw frontend::Usage_error("no method asked applies to these inputs (" + why + ")");
}

std::vector<std::pair<std::string, std::vector<std::string>>> bench_inputs(
    const Bench_arguments& args) {
  for (const auto& method : args.methods) {
    Method parsed;
    if (!parse_method(method, parsed))
      throw frontend::Usage_error("unknown method '" + method + "'");
  }
  if (args.inputs.empty() && (args.bordered || args.closed || args.merge_duplicates)) {
    throw frontend::Usage_error(std::string(args.bordered ? "--bordered"
                                            : args.closed ? "--closed"
                                                          : "--merge-duplicates") +
                                " applies to point files; an example has its own kind and no "
                                "repeated points, the torus is closed");
  }
  std::vector<std::pair<std::string, std::vector<std::string>>> inputs;
  for (const auto& path : args.inputs) {
    std::vector<std::string> source = {"--input", path};
    if (args.bordered) source.push_back("--bordered");
    if (args.closed) source.push_back("--closed");
    if (args.merge_duplicates) source.push_back("--merge-duplicates");
    inputs.emplace_back(path.substr(path.find_last_of('/') + 1), source);
  }
  for (const auto& example : args.examples) {
    if (!shapes::find_example(example))
      throw frontend::Usage_error("unknown example '" + example + "'");
    inputs.push_back({example, {"--example", example}});
  }
  // The cleaning asked travels with each input to the measuring process (files and examples).
  if (args.cleaning != to_string(Options{}.cleaning)) {
    for (auto& input : inputs) {
      if (input.second.front() == "--torus") continue;
      input.second.push_back("--clean");
      input.second.push_back(args.cleaning);
    }
  }
  if (args.torus_points > 0) {
    inputs.emplace_back(fmt::format("torus {}", args.torus_points),
                        std::vector<std::string>{"--torus", std::to_string(args.torus_points)});
  }
  return inputs;
}

// One row: CGAL's Delaunay of the points, CGAL's Advancing Front and every method on the same
// points, each in a process of its own, `runs` times interleaved.
nlohmann::json measure_input(const std::string& name, const std::vector<std::string>& source,
                             const Bench_arguments& args) {
  std::vector<std::string> methods = args.methods;
  if (methods.empty()) methods.assign(method_names().begin(), method_names().end());
  std::vector<std::pair<std::string, std::vector<std::string>>> jobs = {
      {"delaunay", {"--job", "delaunay"}}};
  // CGAL's own run on the raw points, apart from our method of the same name (which also runs
  // stages 1 and 2): its label must not be a method's.
  const std::string cgal_front = "cgal:advancing-front";
  if (args.advancing_front) jobs.push_back({cgal_front, {"--job", "advancing-front"}});
  for (const auto& method : methods)
    jobs.push_back({method, {"--job", "method", "--method", method}});

  std::map<std::string, std::vector<nlohmann::json>> runs;
  for (int run = 0; run < std::max(1, args.runs); ++run) {
    for (auto [label, arguments] : jobs) {
      if (label != "delaunay") {  // measured first: it says the input's dimension
        const int dimension = runs["delaunay"].front().value("dimension", 0);
        if (label == cgal_front && dimension != 3) {
          continue;  // a surface method: not for curves (nor for an input nothing could read)
        }
        Method method;
        if (parse_method(label, method) && !reconstructs_in(method, dimension)) continue;
      }
      arguments.insert(arguments.end(), source.begin(), source.end());
      runs[label].push_back(run_job_process(arguments));
    }
  }
  nlohmann::json row;
  row["input"] = name;
  row["methods"] = nlohmann::json::object();  // none, where no method is for this dimension
  row["delaunay_only"] = median_run(runs["delaunay"]);
  row["samples"] = row["delaunay_only"].value("samples", 0);
  for (const auto& method : methods) {
    if (!runs[method].empty()) row["methods"][method] = median_run(runs[method]);
  }
  if (!runs[cgal_front].empty()) row["advancing_front"] = median_run(runs[cgal_front]);
  return row;
}

// Meshes Loop-subdivided into a folder of their own, as files the measuring processes read;
// the folder goes when the benchmark ends, however it ends.
struct Subdivided_meshes {
  std::filesystem::path folder;
  std::vector<std::string> paths;
  explicit Subdivided_meshes(const std::vector<std::string>& meshes) {
    if (meshes.empty()) return;
    folder = std::filesystem::temp_directory_path() / ("sculpt-bench-" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    for (const auto& mesh : meshes) {
      const frontend::Input input = frontend::load_input(mesh, "", 3);
      if (input.reference_triangles.empty())
        throw io::Error(mesh + ": no triangles to subdivide (a mesh file is needed)");
      const Triangle_mesh dense = loop_subdivided(
          {std::get<std::vector<Point<3>>>(input.points), input.reference_triangles});
      const auto stem = std::filesystem::path(mesh).stem().string();
      paths.push_back((folder / (stem + "-loop1.off")).string());
      io::write_surface(paths.back(), dense.points, dense.triangles, true);
    }
  }
  ~Subdivided_meshes() {
    std::error_code ignored;
    if (!folder.empty()) std::filesystem::remove_all(folder, ignored);
  }
};

int run_bench(const Bench_arguments& given) {
  // Before any work (a benchmark runs for minutes): the JSON table can be written, over no input.
  if (!given.json.empty() && io::extension_of(given.json) != ".json") {
    throw frontend::Usage_error("the JSON table must end in .json: '" + given.json + "'");
  }
  io::check_destination(given.json, given.inputs);
  Bench_arguments args = given;
  const Subdivided_meshes subdivided(args.loop_subdivided);
  args.inputs.insert(args.inputs.end(), subdivided.paths.begin(), subdivided.paths.end());
  const auto inputs = bench_inputs(args);
  if (inputs.empty() && !args.edits && args.render_triangles <= 0) {
    throw frontend::Usage_error(
        "bench needs something to measure: a point file, --example or "
        "--torus N (or --edits, --render-triangles N)");
  }
  if (inputs.empty() && !args.json.empty()) {
    throw frontend::Usage_error(
        "--json writes the rows of the inputs measured (a point file, --example, --torus N); "
        "--edits and --render print their own");
  }
  std::vector<nlohmann::json> rows;
  for (const auto& [name, source] : inputs) {
    rows.push_back(measure_input(name, source, args));
    if (isatty(STDERR_FILENO)) {  // progress for a person watching; never in a log
      std::cerr << "sculpt bench: " << name << " done\n";
    }
  }
  check_a_method_measured(args.methods, rows);
  print_rows(rows);
  // A measurement that failed fails the benchmark (after the table and its JSON, which say which).
  int failed = 0;
  const auto count = [&](const nlohmann::json& measured) { failed += measured.contains("error"); };
  for (const auto& row : rows) {
    count(row["delaunay_only"]);
    for (const auto& [method, measured] : row["methods"].items()) count(measured);
    if (row.contains("advancing_front")) count(row["advancing_front"]);
  }
  if (args.edits) {
    std::vector<nlohmann::json> edits;
    for (int n : {200, 1000, 5000})
      edits.push_back(median_of_runs({"--job", "edit", "--torus", std::to_string(n)}, args.runs));
    for (const auto& edit : edits) count(edit);
    print_edits(edits);
  }
  if (args.render_triangles > 0) {
    const nlohmann::json rendering = median_of_runs(
        {"--job", "render", "--torus", std::to_string(args.render_triangles)}, args.runs);
    count(rendering);
    print_rendering(rendering);
  }
  if (!args.json.empty()) {
    io::Atomic_file file(args.json, false);
    file.stream() << nlohmann::json(rows).dump(2) << '\n';
    file.commit();
  }
  if (failed > 0) {
    throw io::Error(fmt::format("{} measurement{} failed (the table says which)", failed,
                                failed == 1 ? "" : "s"));
  }
  return 0;
}

}  // namespace sculpt::cli
