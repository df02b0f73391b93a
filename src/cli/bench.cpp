#include "bench.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <initializer_list>
#include <iostream>
#include <nlohmann/json.hpp>

#include "frontend/input.hpp"
#include "io/atomic_file.hpp"
#include "io/point_reader.hpp"
#include "render/headless.hpp"
#include "report.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {
namespace {

// Runs `work` in a child process and returns the JSON it produced, with the child's peak memory.
template <class Work>
nlohmann::json in_child_process(Work&& work) {
  int channel[2];
  if (pipe(channel) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(channel[0]);
    std::string text;
    try {
      text = work().dump();
    } catch (const std::exception& e) {
      text = nlohmann::json{{"error", e.what()}}.dump();
    }
    const char* data = text.data();
    for (std::size_t left = text.size(); left > 0;) {
      const auto written = write(channel[1], data, left);
      if (written <= 0) break;
      data += written;
      left -= static_cast<std::size_t>(written);
    }
    _exit(0);
  }
  close(channel[1]);
  std::string text;
  char buffer[65536];
  for (ssize_t got; (got = read(channel[0], buffer, sizeof buffer)) > 0;) text.append(buffer, got);
  close(channel[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  if (text.empty()) return {{"error", "the measuring process died"}};
  auto result = nlohmann::json::parse(text);
  result["process_peak_mib"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return result;
}

// One row: CGAL's Delaunay of the points, then every method on the same points, each in a
// process of its own; a mesh input's own triangles are the reference the results are compared
// with (its topology, and the share of its triangles each method reproduces).
template <int D>
nlohmann::json measure(const std::string& name, const std::vector<Point<D>>& points, bool bordered,
                       const std::vector<Facet<3>>& reference) {
  nlohmann::json row;
  row["input"] = name;
  row["samples"] = points.size();
  if constexpr (D == 3) {
    if (!reference.empty()) {
      const Statistics own = facet_topology(points.size(), reference);
      row["reference"] = {{"triangles", reference.size()},
                          {"euler_characteristic", own.euler_characteristic},
                          {"components", own.components},
                          {"boundary_loops", own.boundary_loops}};
    }
  }
  row["delaunay_only"] = in_child_process([&] {
    return nlohmann::json{{"seconds", delaunay_seconds(points)}};
  });
  for (const char* method_name : method_names()) {
    row["methods"][method_name] = in_child_process([&] {
      Options options;
      parse_method(method_name, options.method);
      options.kind = bordered ? Surface_kind::bordered : Surface_kind::closed;
      options.keep_triangulations = false;
      Run_description run;
      run.input = name;
      run.kind = to_string(options.kind);
      run.rule = to_string(resolved_rule(options));
      const auto result = reconstruct(points, options);
      nlohmann::json json = report_json(result.stats, run);
      if constexpr (D == 3) {
        if (!reference.empty())
          json["reproduced"] = triangles_reproduced(reference, result.surface);
      }
      return json;
    });
  }
  return row;
}

double stage_seconds(const nlohmann::json& stats, std::initializer_list<const char*> names) {
  double sum = 0;
  for (const auto& stage : stats["stages"]) {
    for (const char* name : names) sum += stage["name"] == name ? double(stage["seconds"]) : 0.0;
  }
  return sum;
}

void print_rows(const std::vector<nlohmann::json>& rows) {
  std::cout << fmt::format("\n{:<22}{:>9}{:>9}{:>8}{:>9}{:>9}{:>9}{:>9}{:>9}{:>8}{:>8}\n",
                           "time (s)", "n", "CGAL DT", "method", "ours:DT", "poles", "label",
                           "sculpt", "total", "/ DT", "MiB/DT");
  for (const auto& row : rows) {
    if (row["delaunay_only"].contains("error")) {
      std::cout << fmt::format("{:<22} failed: {}\n", row["input"].get<std::string>(),
                               row["delaunay_only"]["error"].get<std::string>());
      continue;
    }
    const double dt = row["delaunay_only"]["seconds"];
    const double dt_mib = row["delaunay_only"]["process_peak_mib"];
    for (const auto& [method, s] : row["methods"].items()) {
      if (s.contains("error")) {
        std::cout << fmt::format("{:<22} {} failed: {}\n", row["input"].get<std::string>(), method,
                                 s["error"].get<std::string>());
        continue;
      }
      const double total = s["total_seconds"];
      std::cout << fmt::format(
          "{:<22}{:>9}{:>9.3f}{:>8}{:>9.3f}{:>9.3f}{:>9.3f}{:>9.3f}{:>9.3f}{:>8.2f}{:>8.2f}\n",
          row["input"].get<std::string>(), s["samples"].get<std::size_t>(), dt, method,
          stage_seconds(s, {"delaunay"}), stage_seconds(s, {"poles"}),
          stage_seconds(s, {"seeds", "propagation", "labelling"}),
          stage_seconds(s, {"insertion", "carving", "solid", "surface"}), total, total / dt,
          double(s["process_peak_mib"]) / dt_mib);
    }
  }
  std::cout << fmt::format("\n{:<22}{:>8}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
                           "result", "method", "triangles", "non-man.", "n.-m. v", "border",
                           "unused", "pieces", "Euler(own)", "reproduced", "verdict");
  for (const auto& row : rows) {
    const bool has_reference = row.contains("reference");
    for (const auto& [method, s] : row["methods"].items()) {
      if (s.contains("error")) continue;
      const std::string euler =
          has_reference ? fmt::format("{}({})", s["euler_characteristic"].get<long>(),
                                      row["reference"]["euler_characteristic"].get<long>())
                        : std::to_string(s["euler_characteristic"].get<long>());
      const std::string reproduced =
          s.contains("reproduced") ? fmt::format("{:.1f}%", 100 * double(s["reproduced"])) : "";
      std::cout << fmt::format(
          "{:<22}{:>8}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
          row["input"].get<std::string>(), method, s["facets"].get<std::size_t>(),
          s["non_manifold_ridges"].get<std::size_t>(),
          s["non_manifold_vertices"].get<std::size_t>(), s["boundary_ridges"].get<std::size_t>(),
          s["unused_samples"].get<std::size_t>(), s["components"].get<std::size_t>(), euler,
          reproduced, s["manifold"].get<bool>() ? "manifold" : "DEFECTIVE");
    }
  }
}

// A torus surface of about `triangles` triangles (a closed torus has twice as many triangles as
// samples), rendered headless at 1600x1200: building its scene, then two renders (the first
// also makes the context and compiles the shaders).
void bench_rendering(int triangles) {
  const auto samples = shapes::torus(triangles / 2);
  Options options;
  options.keep_triangulations = false;
  const auto result = reconstruct(samples, options);
  const auto measured = in_child_process([&] {
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point since) {
      return std::chrono::duration<double>(Clock::now() - since).count();
    };
    auto start = Clock::now();
    scene::Request request;
    request.stage = scene::Stage::surface;
    const auto scene = scene::build_scene(result, request);
    const double build = seconds(start);
    start = Clock::now();
    render::Headless_renderer renderer;
    const auto camera = render::fit(scene, 1600.0f / 1200.0f);
    renderer.render(scene, camera, 1600, 1200);
    const double first = seconds(start);
    start = Clock::now();
    renderer.render(scene, camera, 1600, 1200);
    return nlohmann::json{{"scene", build},
                          {"first", first},
                          {"second", seconds(start)},
                          {"renderer", renderer.gl_renderer()}};
  });
  if (measured.contains("error")) {
    std::cout << "rendering failed: " << measured["error"].get<std::string>() << '\n';
    return;
  }
  std::cout << fmt::format(
      "\nheadless render, {} triangles at 1600x1200 ({}): scene {:.2f} s, first render {:.2f} s "
      "(context, shaders, upload, draw), next render {:.2f} s, peak {:.0f} MiB\n",
      result.surface.size(), measured["renderer"].get<std::string>(), double(measured["scene"]),
      double(measured["first"]), double(measured["second"]), double(measured["process_peak_mib"]));
}

}  // namespace

int run_bench(const Bench_arguments& args) {
  std::vector<nlohmann::json> rows;
  const auto add = [&](nlohmann::json row) {
    if (isatty(STDERR_FILENO)) {  // progress for a person watching; never in a log
      std::cerr << "sculpt bench: " << row["input"].get<std::string>() << " done\n";
    }
    rows.push_back(std::move(row));
  };
  const auto measure_input = [&](const std::string& path, const std::string& example) {
    const frontend::Input input = frontend::load_input(path, example, 0, args.merge_duplicates);
    const std::string name = example.empty() ? path.substr(path.find_last_of('/') + 1) : example;
    const bool bordered = example.empty() ? args.bordered : shapes::find_example(example)->bordered;
    std::visit(
        [&](const auto& points) {
          constexpr int D = std::tuple_size_v<typename std::decay_t<decltype(points)>::value_type>;
          add(measure<D>(name, points, bordered, input.reference_triangles));
        },
        input.points);
  };
  for (const auto& path : args.inputs) measure_input(path, "");
  for (const auto& example : args.examples) measure_input("", example);
  if (args.torus_points > 0) {
    add(measure<3>(fmt::format("torus {}", args.torus_points), shapes::torus(args.torus_points),
                   false, {}));
  }
  print_rows(rows);
  if (args.render_triangles > 0) bench_rendering(args.render_triangles);
  if (!args.json.empty()) {
    io::Atomic_file file(args.json, false);
    file.stream() << nlohmann::json(rows).dump(2) << '\n';
    file.commit();
  }
  return 0;
}

}  // namespace sculpt::cli
