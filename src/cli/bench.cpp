// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "frontend/command_line.hpp"
#include "frontend/input.hpp"
#include "frontend/shot.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"
#include "render/headless.hpp"
#include "report.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {
namespace {

// The peak resident memory of this process's own image, in MiB (VmHWM). Unlike the rusage
// maximum, it does not carry over the memory of the parent that forked it (Linux keeps that high
// mark across exec): a job started by a large process reports its own peak.
double own_peak_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  }
  return 0;
}

// The CPU seconds (user + system) a resource usage records.
double cpu_seconds(const rusage& usage) {
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Runs this executable as `sculpt bench-job ARGUMENTS...` and returns the JSON it prints, with
// the process's CPU time (user + system), wall time and peak resident memory.
nlohmann::json run_job_process(const std::vector<std::string>& arguments) {
  std::vector<std::string> words = {"sculpt", "bench-job"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  int channel[2];
  if (pipe(channel) != 0) throw std::runtime_error("pipe failed");
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child < 0) {
    close(channel[0]);
    close(channel[1]);
    throw std::runtime_error("fork failed");
  }
  if (child == 0) {
    dup2(channel[1], STDOUT_FILENO);
    close(channel[0]);
    close(channel[1]);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  close(channel[1]);
  std::string text;
  char buffer[65536];
  for (ssize_t got; (got = read(channel[0], buffer, sizeof buffer)) > 0;) text.append(buffer, got);
  close(channel[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) {
    return {{"error", "the measuring process died"}};
  }
  auto result = nlohmann::json::parse(text, nullptr, false);
  if (result.is_discarded()) return {{"error", "the measuring process wrote no JSON"}};
  // Less the time the job spent judging its result (Evaluation_time).
  const auto judging = result.value("evaluation", nlohmann::json::object());
  result["process"] = {
      {"cpu_seconds", cpu_seconds(usage) - judging.value("cpu_seconds", 0.0)},
      {"wall_seconds", wall - judging.value("wall_seconds", 0.0)},
      {"peak_mib", result.value("own_peak_mib", double(usage.ru_maxrss) / 1024.0)}};
  return result;
}

// Of several runs of one measurement, the one of median CPU time.
nlohmann::json median_run(std::vector<nlohmann::json> runs) {
  std::vector<nlohmann::json> good;
  for (auto& run : runs) {
    if (!run.contains("error")) good.push_back(std::move(run));
  }
  if (good.empty()) return runs.front();
  std::sort(good.begin(), good.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return double(a["process"]["cpu_seconds"]) < double(b["process"]["cpu_seconds"]);
  });
  return good[(good.size() - 1) / 2];
}

// One job measured `runs` times, each in a fresh process: the median run.
nlohmann::json median_of_runs(const std::vector<std::string>& arguments, int runs) {
  std::vector<nlohmann::json> measured;
  for (int run = 0; run < std::max(1, runs); ++run) measured.push_back(run_job_process(arguments));
  return median_run(std::move(measured));
}

double stage_seconds(const nlohmann::json& stats, std::initializer_list<const char*> names) {
  double sum = 0;
  for (const auto& stage : stats["stages"]) {
    for (const char* name : names) sum += stage["name"] == name ? double(stage["seconds"]) : 0.0;
  }
  return sum;
}

// The stages every method shares; the rest are the method's own, whatever their names.
const std::initializer_list<const char*> shared_stages = {"checks", "delaunay", "poles",
                                                          "topology"};

double own_stage_seconds(const nlohmann::json& stats) {
  double sum = 0;
  for (const auto& stage : stats["stages"]) sum += double(stage["seconds"]);
  return sum - stage_seconds(stats, shared_stages);
}

void print_rows(const std::vector<nlohmann::json>& rows) {
  std::cout
      << "\nWhole process: CPU seconds and peak memory of a process that reads the input and "
         "runs one job,\nless what it spends judging its result against the input's mesh.\nx DT: "
         "against the process that reads the same input and builds "
         "CGAL's Delaunay triangulation of it.\nThe stage columns (and DT core) are wall-clock "
         "seconds inside the process.\n";
  std::cout << fmt::format("\n{:<20}{:>9}{:>17}{:>17}{:>8}{:>8}{:>8}{:>8}{:>8}{:>9}{:>7}{:>8}\n",
                           "input", "n", "method", "DT core / whole", "delaun.", "poles", "method",
                           "topol.", "read", "whole s", "x DT", "MiB xDT");
  for (const auto& row : rows) {
    const auto& dt = row["delaunay_only"];
    const std::string input = row["input"].get<std::string>();
    if (dt.contains("error")) {
      std::cout << fmt::format("{:<20} failed: {}\n", input, dt["error"].get<std::string>());
      continue;
    }
    const double dt_whole = dt["process"]["cpu_seconds"];
    const double dt_mib = dt["process"]["peak_mib"];
    const std::string dt_text = fmt::format("{:.3f} / {:.3f}", double(dt["seconds"]), dt_whole);
    const auto print = [&](const std::string& label, const nlohmann::json& s) {
      if (s.contains("error")) {
        std::cout << fmt::format("{:<20}{:>9}{:>17}  failed: {}\n", input, "", label,
                                 s["error"].get<std::string>());
        return;
      }
      const double whole = s["process"]["cpu_seconds"];
      const bool staged = s.contains("stages") && !s["stages"].empty();
      const auto cell = [&](std::initializer_list<const char*> names) {
        return staged ? fmt::format("{:.3f}", stage_seconds(s, names)) : std::string("");
      };
      std::cout << fmt::format(
          "{:<20}{:>9}{:>17}{:>17}{:>8}{:>8}{:>8}{:>8}{:>8.3f}{:>9.3f}{:>7.2f}{:>8.2f}\n", input,
          row["samples"].get<std::size_t>(), label, dt_text, cell({"checks", "delaunay"}),
          cell({"poles"}), staged ? fmt::format("{:.3f}", own_stage_seconds(s)) : std::string(""),
          cell({"topology"}), double(s.value("read_seconds", 0.0)), whole, whole / dt_whole,
          double(s["process"]["peak_mib"]) / dt_mib);
    };
    for (const auto& [method, s] : row["methods"].items()) print(method, s);
    if (row.contains("advancing_front")) print("CGAL adv. front", row["advancing_front"]);
  }

  std::cout << fmt::format("\n{:<20}{:>17}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
                           "result", "method", "triangles", "non-man.", "n.-m. v", "border",
                           "unused", "pieces", "Euler(own)", "reproduced", "verdict");
  for (const auto& row : rows) {
    const bool has_reference = row["delaunay_only"].contains("reference");
    const auto print = [&](const std::string& label, const nlohmann::json& s) {
      if (s.contains("error")) return;
      const std::string euler =
          has_reference
              ? fmt::format("{}({})", s["euler_characteristic"].get<long>(),
                            row["delaunay_only"]["reference"]["euler_characteristic"].get<long>())
              : std::to_string(s["euler_characteristic"].get<long>());
      const std::string reproduced =
          s.contains("reproduced") ? fmt::format("{:.1f}%", 100 * double(s["reproduced"])) : "";
      std::cout << fmt::format(
          "{:<20}{:>17}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
          row["input"].get<std::string>(), label, s["facets"].get<std::size_t>(),
          s["non_manifold_ridges"].get<std::size_t>(),
          s["non_manifold_vertices"].get<std::size_t>(), s["boundary_ridges"].get<std::size_t>(),
          s["unused_samples"].get<std::size_t>(), s["components"].get<std::size_t>(), euler,
          reproduced, s["manifold"].get<bool>() ? "manifold" : "DEFECTIVE");
    };
    for (const auto& [method, s] : row["methods"].items()) print(method, s);
    if (row.contains("advancing_front")) print("CGAL adv. front", row["advancing_front"]);
  }
}

// The CPU seconds (user + system) this process has used so far.
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return cpu_seconds(usage);
}

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

void print_edits(const std::vector<nlohmann::json>& rows) {
  std::cout << "\nlive 2D edit (viewer): one sample moved, reconstructed with every stage kept "
               "(robust), Voronoi and curve scenes built; median of 21 edits\n";
  std::cout << fmt::format("{:>8}  {:>13}  {:>9}  {:>9}  {:>6}\n", "samples", "reconstruct",
                           "scenes", "per edit", "x DT");
  for (const auto& row : rows) {
    if (row.contains("error")) {
      std::cout << "edit timing failed: " << row["error"].get<std::string>() << '\n';
      continue;
    }
    const double total = double(row["reconstruct"]) + double(row["scene"]);
    std::cout << fmt::format("{:>8}  {:>10.1f} ms  {:>6.1f} ms  {:>6.1f} ms  {:>6.1f}\n",
                             row["samples"].get<int>(), 1e3 * double(row["reconstruct"]),
                             1e3 * double(row["scene"]), 1e3 * total,
                             double(row["reconstruct"]) / double(row["delaunay"]));
  }
}

void print_rendering(const nlohmann::json& measured) {
  if (measured.contains("error")) {
    std::cout << "rendering failed: " << measured["error"].get<std::string>() << '\n';
    return;
  }
  std::cout << fmt::format(
      "\nheadless render, {} triangles at 1600x1200 ({}): scene {:.2f} s, first render {:.2f} s "
      "(module, context, shaders, upload, draw), next render {:.2f} s, peak {:.0f} MiB\n",
      measured["triangles"].get<std::size_t>(), measured["renderer"].get<std::string>(),
      double(measured["scene"]), double(measured["first"]), double(measured["second"]),
      double(measured["process"]["peak_mib"]));
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
    out = {{"error", e.what()}};
  }
  out["own_peak_mib"] = own_peak_mib();
  std::cout << out.dump() << '\n';
  return 0;
}

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
