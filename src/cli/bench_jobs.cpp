// SPDX-License-Identifier: GPL-3.0-or-later
// The measuring jobs of `sculpt bench`, each run in a process of its own (`sculpt bench-job`):
// CGAL's Delaunay triangulation, CGAL's Advancing Front or a method on one input, a headless
// render, the viewer's live 2D edit. Each prints its JSON on standard output.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bench.hpp"
#include "bench_process.hpp"
#include "frontend/command_line.hpp"
#include "frontend/failure.hpp"
#include "frontend/input.hpp"
#include "frontend/shot.hpp"
#include "render/headless.hpp"
#include "report.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {
namespace {

// A job also judges what it made: the share of the input mesh's triangles reproduced, the
// topology of the mesh and of CGAL's Advancing Front's result. The work being measured does none
// of that (the Advancing Front does not check its result; Sculpt's own topology stage is part of
// every method and stays in), so its time is recorded apart and taken off the process's
// (run_job_process). Bunny00 subdivided: 0.022 s in the Delaunay's job, 0.054 in robust's,
// 0.082 in the Advancing Front's.
class Evaluation_time {
 public:
  template <class Work>
  void measure(Work&& work) {
    const double cpu = process_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    work();
    cpu_seconds_ += process_cpu_seconds() - cpu;
    wall_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  nlohmann::json json() const {
    return {{"cpu_seconds", cpu_seconds_}, {"wall_seconds", wall_seconds_}};
  }

 private:
  double cpu_seconds_ = 0, wall_seconds_ = 0;
};

template <int D>
nlohmann::json run_job_on(const std::vector<Point<D>>& points, const frontend::Input& input,
                          const Bench_job& job) {
  nlohmann::json out;
  Evaluation_time evaluation;
  const auto add_reproduced = [&](const std::vector<Facet<D>>& facets) {
    if constexpr (D == 3) {
      if (input.reference_triangles.empty()) return;
      evaluation.measure(
          [&] { out["reproduced"] = triangles_reproduced(input.reference_triangles, facets); });
    }
  };
  if (job.job == "delaunay") {
    out["seconds"] = delaunay_seconds(points);
    if constexpr (D == 3) {
      if (!input.reference_triangles.empty()) {
        evaluation.measure([&] {
          const Statistics own = facet_topology(points.size(), input.reference_triangles);
          out["reference"] = {{"triangles", input.reference_triangles.size()},
                              {"euler_characteristic", own.euler_characteristic},
                              {"components", own.components},
                              {"boundary_loops", own.boundary_loops}};
        });
      }
    }
  } else if (job.job == "advancing-front") {
    if constexpr (D == 3) {
      const auto start = std::chrono::steady_clock::now();
      const auto facets = cgal_advancing_front(points);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      Statistics stats;
      evaluation.measure([&] { stats = facet_topology(points.size(), facets); });
      Run_description run;
      run.input = input.description;
      out = report_json(stats, run);
      out["method"] = "advancing-front";
      out["total_seconds"] = seconds;
      add_reproduced(facets);
    } else {
      throw Input_error("the Advancing Front reconstructs surfaces only");
    }
  } else {
    Options options;
    if (!parse_method(job.method, options.method))
      throw Input_error("unknown method " + job.method);
    options.kind = frontend::input_kind(shapes::find_example(job.example), job.bordered,
                                        job.closed);  // an example is its own kind
    if (!parse_cleaning(job.cleaning, options.cleaning))
      throw Input_error("unknown cleaning " + job.cleaning);
    options.keep_triangulations = false;
    options.keep_solid = false;  // as `sculpt reconstruct` without --solid
    Run_description run;
    run.input = input.description;
    const auto result = reconstruct(points, options);
    run.rule = surface_rule_name(result.options, D);
    out = report_json(result.stats, run);
    if (result.interpolates()) add_reproduced(result.surface);  // else: vertices of its own
  }
  out["samples"] = points.size();
  out["dimension"] = D;
  out["read_seconds"] = input.read_seconds;
  out["evaluation"] = evaluation.json();
  return out;
}

// The render job: a torus surface of about `triangles` triangles (a closed torus has twice as
// many triangles as samples) drawn headless at 1600x1200: building its scene, then two renders
// (the first also loads the module, makes the context and compiles the shaders).
nlohmann::json render_job(int triangles) {
  const auto samples = shapes::torus(triangles / 2);
  Options options;
  options.keep_triangulations = false;
  const auto result = reconstruct(samples, options);
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
  return {{"triangles", result.surface.size()},
          {"scene", build},
          {"first", first},
          {"second", seconds(start)},
          {"renderer", renderer.gl_renderer()}};
}

// The viewer's live 2D edit on `n` samples of the blob: one sample moved a little, the points
// reconstructed with every stage kept (as the viewer does), and the scene of the Voronoi stage
// (the busiest 2D picture) and of the curve built; the median of 21 edits, beside CGAL's
// Delaunay triangulation of the same points.
nlohmann::json edit_job(int n) {
  if (n < 3) throw std::invalid_argument("an edit needs at least 3 samples");
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point since) {
    return std::chrono::duration<double>(Clock::now() - since).count();
  };
  auto points = shapes::blob(n).samples;
  Options options;
  options.keep_triangulations = true;
  std::vector<double> reconstruct_times, scene_times, delaunay_times;
  for (int edit = 0; edit < 21; ++edit) {
    Point<2>& moved = points[(edit * 7919) % n];
    moved[0] += edit % 2 ? -1e-3 : 1e-3;
    delaunay_times.push_back(delaunay_seconds(points));
    auto start = Clock::now();
    const auto result = reconstruct(points, options);
    reconstruct_times.push_back(seconds(start));
    start = Clock::now();
    for (scene::Stage stage : {scene::Stage::voronoi, scene::Stage::surface}) {
      scene::Request request;
      request.stage = stage;
      scene::build_scene(result, request);
    }
    scene_times.push_back(seconds(start));
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  return {{"samples", n},
          {"reconstruct", median(reconstruct_times)},
          {"scene", median(scene_times)},
          {"delaunay", median(delaunay_times)}};
}

}  // namespace

int run_bench_job(const Bench_job& job) {
  nlohmann::json out;
  try {
    if (job.job == "render") {
      std::cout << render_job(job.torus_points).dump() << '\n';
      return 0;
    }
    if (job.job == "edit") {
      std::cout << edit_job(job.torus_points).dump() << '\n';
      return 0;
    }
    frontend::Input input;
    if (job.torus_points > 0) {
      const auto start = std::chrono::steady_clock::now();
      input.points = shapes::torus(job.torus_points);
      input.description = fmt::format("torus {}", job.torus_points);
      input.read_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } else {
      input = frontend::load_input(job.input, job.example, 0, job.merge_duplicates);
    }
    out = std::visit(
        [&](const auto& points) {
          constexpr int D = std::tuple_size_v<typename std::decay_t<decltype(points)>::value_type>;
          return run_job_on<D>(points, input, job);
        },
        input.points);
  } catch (const std::exception& e) {
    // In the words `sculpt` itself uses (with its hints), without "error: ".
    const std::string line = frontend::failure_line(e), prefix = "error: ";
    out = {{"error", line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line}};
  }
  out["own_peak_mib"] = own_peak_mib();
  std::cout << out.dump() << '\n';
  return 0;
}

}  // namespace sculpt::cli
