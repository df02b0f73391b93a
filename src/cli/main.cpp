// SPDX-License-Identifier: GPL-3.0-or-later
// The `sculpt` command: reconstruct a curve or surface from a point file, or from a built-in
// example, and write it with the sculpted solid and the run's statistics.
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <limits>

#include "bench.hpp"
#include "compare.hpp"
#include "figures/gallery.hpp"
#include "frontend/command_line.hpp"
#include "frontend/failure.hpp"
#include "frontend/input.hpp"
#include "frontend/option_use.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "io/result_files.hpp"
#include "io/temporary_files.hpp"
#include "io/writers.hpp"
#include "progress_display.hpp"
#include "render_command.hpp"
#include "report.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {
namespace {

struct Reconstruct_arguments {
  std::string input, example, output, solid, stats, rule = "auto";
  std::string cleaning = to_string(Options{}.cleaning);
  std::string method = to_string(Options{}.method);
  int dimension = 0;  // 0: as the input says
  int seed_sample = Options{}.bordered_seed_sample;
  double box_factor = Options{}.box_factor;
  double alpha = Options{}.alpha;
  bool bordered = false, closed = false, automatic = false, ascii = false, quiet = false,
       merge_duplicates = false;
  bool require_manifold = false;
};

using frontend::exit_bad_input;
using frontend::exit_bad_usage;

using frontend::Usage_error;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Fails before any work is done if an output's extension is not one Sculpt can write.
void check_output_formats(const Reconstruct_arguments& args, int dimension) {
  const std::string surface = io::extension_of(args.output);
  if (!(dimension == 3 ? io::writes_surface(surface) : io::writes_curve(surface))) {
    throw Usage_error(fmt::format("cannot write a {} as '{}' (known: {})",
                                  dimension == 3 ? "surface" : "curve", args.output,
                                  dimension == 3 ? io::surface_formats : io::curve_formats));
  }
  if (!args.solid.empty()) {
    if (!io::writes_solid(io::extension_of(args.solid))) {
      throw Usage_error(
          fmt::format("cannot write a solid as '{}' (known: {})", args.solid, io::solid_formats));
    }
    Method method;
    if (parse_method(args.method, method) && !builds_solid(method)) {
      throw Usage_error(frontend::no_solid_message(method));
    }
  }
  if (!args.stats.empty() && io::extension_of(args.stats) != ".json") {
    throw Usage_error("the statistics file must end in .json: '" + args.stats + "'");
  }
  // Before any work: every output can be written, none is the input, no two are the same file.
  io::check_destinations(io::with_companions({args.output, args.solid, args.stats}), {args.input});
}

// The reconstruction the arguments ask for (method and rule were checked by CLI11). The command
// line keeps no triangulation.
Options options_of(const Reconstruct_arguments& args, Surface_kind kind) {
  Options options;
  parse_method(args.method, options.method);
  options.kind = kind;
  parse_rule(args.rule, options.rule);
  parse_cleaning(args.cleaning, options.cleaning);
  options.box_factor = args.box_factor;
  options.alpha = args.alpha;
  options.bordered_seed_sample = args.seed_sample;
  options.keep_triangulations = false;
  return options;
}

// An option the method or kind would never read is refused, not ignored.
void check_options_apply(const Reconstruct_arguments& args, Surface_kind kind) {
  const Options options = options_of(args, kind);
  const auto spelling = frontend::Spelling::command_line;
  for (const std::string& problem :
       {frontend::unused_reconstruction_option(options, spelling),
        args.automatic ? frontend::unused_automatic_kind(options.method, spelling) : "",
        args.ascii ? frontend::unused_ascii(args.output, spelling) : "",
        frontend::unused_input_option(args.example, args.dimension, args.merge_duplicates,
                                      spelling)}) {
    if (!problem.empty()) throw Usage_error(problem);
  }
}

// What became of the samples' normals and colours in the surface file, for the report.
template <int D>
std::string attributes_note(const Reconstruction<D>& result, const Point_attributes& attributes,
                            const std::string& path) {
  if (attributes.empty() || D == 2) return "";
  const std::string what = !attributes.normals.empty() && !attributes.colors.empty()
                               ? "normals and colours"
                           : !attributes.normals.empty() ? "normals"
                                                         : "colours";
  if (io::writes_attributes(result, attributes, path)) return " (with the samples' " + what + ")";
  if (!result.interpolates()) {
    return " (without the samples' " + what + ": the surface's vertices are not the samples)";
  }
  return " (without the samples' " + what + ": " + io::extension_of(path) +
         " has no place for them; .ply and .obj do)";
}

template <int D>
int reconstruct_and_write(const std::vector<Point<D>>& samples, const Point_attributes& attributes,
                          const Reconstruct_arguments& args, Surface_kind kind,
                          Run_description run) {
  Options options = options_of(args, kind);
  options.keep_solid = !args.solid.empty();
  options.progress = progress_display(samples.size(), args.quiet);

  const Reconstruction<D> result = reconstruct(samples, options);
  clear_progress_display();
  run.rule = surface_rule_name(result.options, D);

  // All outputs or none: each is written under a temporary name, and all are renamed at the end.
  const auto start = std::chrono::steady_clock::now();
  io::Output_set outputs;
  io::stage_result(outputs, result, args.output, args.solid, args.ascii, attributes);
  run.write_seconds = seconds_since(start);
  if (!args.stats.empty()) {
    io::Atomic_file file(outputs.stage(args.stats), false);
    file.stream() << report_json(result.stats, run).dump(2) << '\n';
    file.commit();
  }
  outputs.commit();
  const Verdict verdict = sculpt::verdict(result.stats);
  if (!args.quiet) {
    print_report(std::cout, result.stats, run);
    std::cout << "  wrote " << args.output << attributes_note(result, attributes, args.output)
              << (args.solid.empty() ? "" : " and " + args.solid) << '\n';
    std::cout << "verdict: " << verdict.line << '\n';
  }
  if (!verdict.manifold) {
    std::cerr << "sculpt: warning: " << verdict.line << '\n';  // never silent on broken output
  }
  return verdict.manifold || !args.require_manifold ? frontend::exit_success
                                                    : frontend::exit_defective_result;
}

int run_reconstruct(const Reconstruct_arguments& args) {
  // An example is reconstructed as its own kind, as in the viewer, render and the benchmark; a
  // file as --closed or --bordered say, else of the kind chosen automatically.
  const Surface_kind kind =
      args.automatic
          ? Surface_kind::automatic
          : frontend::input_kind(shapes::find_example(args.example), args.bordered, args.closed);
  check_options_apply(args, kind);  // before any work
  const frontend::Input input =
      frontend::load_input(args.input, args.example, args.dimension, args.merge_duplicates);
  check_output_formats(args, input.dimension());
  for (const std::string& warning : input.warnings)
    std::cerr << "sculpt: warning: " << warning << '\n';
  Run_description run;
  run.input = input.description;
  run.box_factor = args.box_factor;
  run.read_seconds = input.read_seconds;
  return std::visit(
      [&](const auto& points) {
        constexpr int dimension =
            std::tuple_size_v<typename std::decay_t<decltype(points)>::value_type>;
        return reconstruct_and_write<dimension>(points, input.attributes, args, kind, run);
      },
      input.points);
}

int run_examples() {
  for (const auto& example : shapes::examples()) {
    std::cout << fmt::format("  {:<18}{}D  {}\n", example.name, example.dimension,
                             example.description);
  }
  return 0;
}

}  // namespace
}  // namespace sculpt::cli

int main(int argc, char** argv) {
  using namespace sculpt::cli;
  CLI::App app{"Sculpt: curve and surface reconstruction by Delaunay sculpting (Kuo & Yau 2003)"};
  app.set_version_flag("--version", std::string("sculpt ") + sculpt::version());
  app.require_subcommand(1);

  Reconstruct_arguments args;
  auto* reconstruct = app.add_subcommand(
      "reconstruct", "Reconstruct a curve (2D points) or surface (3D points) from a point file");
  auto* input = reconstruct->add_option("input", args.input,
                                        std::string("Points: ") + sculpt::io::point_formats);
  auto* example = reconstruct->add_option("--example", args.example,
                                          "Use a built-in example instead (see `sculpt examples`)");
  input->excludes(example);
  reconstruct
      ->add_option("-o,--output", args.output,
                   "Surface .stl .ply .off .obj (3D) or curve .obj .svg (2D)")
      ->required();
  reconstruct->add_option("--method", args.method, sculpt::frontend::methods_help())
      ->capture_default_str()
      ->check(CLI::IsMember(sculpt::method_names()));
  reconstruct->add_flag("--require-manifold", args.require_manifold,
                        "Exit with code 3 when the result is not a closed (or, bordered, a "
                        "bordered) 2-manifold through every sample, of the kind kept; the output "
                        "is still written");
  reconstruct->add_flag("--bordered", args.bordered,
                        "The samples come from a surface (curve) with a border. Without "
                        "--bordered or --closed, an example is reconstructed as its own kind and "
                        "a file as its samples show: closed, unless the closed result spans "
                        "openings and the bordered one has fewer defects");
  reconstruct
      ->add_flag("--closed", args.closed,
                 "The samples come from a closed surface (curve); also for a bordered example")
      ->excludes("--bordered");
  reconstruct
      ->add_flag("--automatic", args.automatic,
                 "Choose the kind from the samples, also for an example (a file's default)")
      ->excludes("--bordered")
      ->excludes("--closed");
  reconstruct->add_option("--solid", args.solid,
                          "Also write the sculpted solid: .mesh (Medit), .vtu, .node/.ele");
  reconstruct
      ->add_option("--box-factor", args.box_factor, "Bounding box BB relative to the samples' box")
      ->capture_default_str()
      ->check(CLI::Range(1.0 + 1e-9, 1e6));
  reconstruct
      ->add_option("--alpha", args.alpha,
                   "alpha-shape: the radius alpha, in the input's units (default: the smallest "
                   "giving one solid with every sample)")
      ->check(sculpt::frontend::positive_length());
  reconstruct
      ->add_option("--rule", args.rule,
                   "Surface rule: auto (skin when closed, extraction when bordered), "
                   "skin or extraction")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "skin", "extraction"}));
  reconstruct
      ->add_option("--clean", args.cleaning,
                   "Clean the samples first (3D): outliers (remove samples far off their "
                   "neighbours' surface), jet (CGAL's jet smoothing), outliers+jet, none, or auto "
                   "(both, for the robust method, where the measured noise is at least 0.3 of the "
                   "spacing: noise that crumples an interpolating surface). The surface passes "
                   "through the cleaned samples; the report and the verdict say so")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "none", "outliers", "jet", "outliers+jet"}));
  reconstruct
      ->add_option("--seed-sample", args.seed_sample,
                   "Bordered: seed with the convex pole of this sample (-1: chosen)")
      ->check(CLI::Range(-1, std::numeric_limits<int>::max()));
  reconstruct
      ->add_option("--dim", args.dimension,
                   "Force 2 or 3 dimensions (2 drops a constant coordinate)")
      ->check(CLI::IsMember({2, 3}));
  reconstruct->add_flag("--ascii", args.ascii, "Write .stl and .ply as text");
  reconstruct->add_flag("--merge-duplicates", args.merge_duplicates,
                        "Remove repeated points instead of refusing them (output vertices are "
                        "then the distinct samples, in input order)");
  reconstruct->add_option("--stats", args.stats, "Write the statistics as JSON");
  reconstruct->add_flag("-q,--quiet", args.quiet, "Print nothing but errors");

  auto* examples = app.add_subcommand("examples", "List the built-in examples");

  sculpt::figures::Options figure_options;
  auto* figures_command = app.add_subcommand(
      "figures", "Regenerate the paper's figures and tables, headless, with a gallery page");
  figures_command->add_option("--out", figure_options.out, "Folder of the images")
      ->capture_default_str();
  figures_command->add_option("--only", figure_options.only, "One figure, e.g. fig06");
  figures_command->add_option("--size", figure_options.size, "Image size")->capture_default_str();
  figures_command
      ->add_option("--cgal-data", figure_options.cgal_archive,
                   "CGAL's data archive (Debian's libcgal-demo)")
      ->capture_default_str();

  Render_arguments render_args;
  add_render_command(app, render_args);
  auto* render = app.get_subcommand("render");

  Bench_arguments bench_args;
  auto* bench = app.add_subcommand(
      "bench",
      "Every method and CGAL's Advancing Front next to CGAL's Delaunay of the same points, each "
      "run in a process of its own: whole-process CPU time and peak memory, and stage times");
  bench->add_option("inputs", bench_args.inputs, "Point files");
  bench->add_option("--example", bench_args.examples, "Built-in examples");
  bench->add_option("--torus", bench_args.torus_points, "Also N random points on a torus")
      ->check(sculpt::frontend::whole_number_above_zero());
  bench->add_option("--loop-subdivided", bench_args.loop_subdivided,
                    "Also these meshes after one step of Loop subdivision (about 4 times the "
                    "vertices, on the same surface)");
  bench
      ->add_option("--render", bench_args.render_triangles,
                   "Also time a headless 1600x1200 render of a surface of N triangles")
      ->check(sculpt::frontend::whole_number_above_zero());
  bench->add_flag("--edits", bench_args.edits,
                  "Also time the viewer's live 2D edit on 200, 1,000 and 5,000 points");
  bench->add_flag("--bordered", bench_args.bordered, "Treat the point files as bordered")
      ->excludes(bench->add_flag("--closed", bench_args.closed,
                                 "Treat the point files as closed (without either, the robust "
                                 "method chooses each file's kind)"));
  bench->add_flag("--merge-duplicates", bench_args.merge_duplicates,
                  "Remove repeated points of the files instead of refusing them");
  bench->add_option("--json", bench_args.json, "Also write the measurements as JSON");
  bench
      ->add_option("--runs", bench_args.runs, "Run every measurement N times, interleaved: medians")
      ->check(CLI::Range(1, 99))
      ->capture_default_str();
  bench->add_option("--methods", bench_args.methods, "Only these methods (default: all)")
      ->delimiter(',');
  bench->add_flag("!--no-advancing-front", bench_args.advancing_front,
                  "Leave out CGAL's Advancing Front");

  Compare_arguments compare_args;
  auto* compare = app.add_subcommand(
      "compare",
      "The methods side by side on the same inputs: a markdown table (time and memory against "
      "CGAL's Delaunay of the same points, the verdict and its counts; against a reference mesh "
      "the triangles reproduced and the Hausdorff distance) and a picture grid");
  compare->add_option("inputs", compare_args.inputs.inputs, "Point files or meshes");
  compare->add_option("--example", compare_args.inputs.examples, "Built-in examples");
  compare->add_option("--methods", compare_args.inputs.methods, "Only these methods (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(sculpt::method_names()));
  compare->add_option("--reference", compare_args.reference,
                      "A mesh to measure the results of the (one) input against; a mesh input "
                      "is its own reference");
  compare->add_flag("--bordered", compare_args.inputs.bordered, "Treat the point files as bordered")
      ->excludes(compare->add_flag("--closed", compare_args.inputs.closed,
                                   "Treat the point files as closed (without either, the robust "
                                   "method chooses each file's kind)"));
  compare->add_flag("--merge-duplicates", compare_args.inputs.merge_duplicates,
                    "Remove repeated points of the files instead of refusing them");
  compare
      ->add_option("--clean", compare_args.inputs.cleaning,
                   "Clean the samples first (3D), for every method: auto, none, outliers, jet or "
                   "outliers+jet (as reconstruct's)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "none", "outliers", "jet", "outliers+jet"}));
  compare->add_option("--runs", compare_args.inputs.runs, "Time every method N times: medians")
      ->check(CLI::Range(1, 99))
      ->capture_default_str();
  compare->add_option("--markdown", compare_args.markdown, "Also write the table to this .md file");
  compare->add_option("--json", compare_args.json, "Also write the measurements as JSON");
  compare->add_option("--pictures", compare_args.pictures,
                      "Write a picture grid (inputs by methods, one camera per input) to this PNG");
  compare->add_option("--tile", compare_args.tile, "Size of one picture of the grid, WxH")
      ->capture_default_str();

  // One measurement of the benchmark, in a process of its own; not for people (no help entry).
  Bench_job bench_job;
  auto* bench_job_command = app.add_subcommand("bench-job", "");
  bench_job_command->group("");
  bench_job_command->add_option("--job", bench_job.job)->required();
  bench_job_command->add_option("--method", bench_job.method);
  bench_job_command->add_option("--input", bench_job.input);
  bench_job_command->add_option("--example", bench_job.example);
  bench_job_command->add_option("--torus", bench_job.torus_points);
  bench_job_command->add_flag("--bordered", bench_job.bordered);
  bench_job_command->add_flag("--closed", bench_job.closed);
  bench_job_command->add_flag("--merge-duplicates", bench_job.merge_duplicates);
  bench_job_command->add_option("--clean", bench_job.cleaning);

  app.footer(sculpt::frontend::exit_codes_help);
  for (CLI::App* command : app.get_subcommands({}))
    command->footer(sculpt::frontend::exit_codes_help);
  if (const auto stop = sculpt::frontend::parse_command_line(app, argc, argv, "sculpt"))
    return *stop;
  sculpt::io::remove_temporaries_on_signals();
  // Every failure is one line on stderr, after the status line is erased.
  const auto fail = [](int code, const std::string& message) {
    clear_progress_display();
    std::cerr << "sculpt: " << sculpt::frontend::one_line(message) << '\n';
    return code;
  };
  const auto run = [&]() -> int {
    if (examples->parsed()) return run_examples();
    if (bench->parsed()) return run_bench(bench_args);
    if (compare->parsed()) return run_compare(compare_args);
    if (bench_job_command->parsed()) return run_bench_job(bench_job);
    if (render->parsed()) return run_render(render_args);
    if (figures_command->parsed()) {
      try {
        sculpt::frontend::parse_size(figure_options.size);  // before any work
      } catch (const sculpt::io::Error& e) {
        throw Usage_error(std::string("--size: ") + e.what());
      }
      return sculpt::figures::generate(figure_options) > 0 ? 0 : 1;
    }
    if (args.input.empty() && args.example.empty()) {
      throw Usage_error("give an input file or --example NAME");
    }
    return run_reconstruct(args);
  };
  try {
    const int code = run();
    // A report that could not be written (a full disk behind stdout) is a failure, not a success.
    if (!std::cout.flush()) {
      return fail(exit_bad_input, "error: cannot write the report to standard output");
    }
    return code;
  } catch (const Usage_error& e) {
    return fail(exit_bad_usage, std::string("usage error: ") + e.what() + " (see sculpt --help)");
  } catch (const std::exception& e) {
    return fail(exit_bad_input, sculpt::frontend::failure_line(e));
  }
}
