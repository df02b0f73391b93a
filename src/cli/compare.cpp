// SPDX-License-Identifier: GPL-3.0-or-later
#include "compare.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

#include "frontend/command_line.hpp"
#include "frontend/input.hpp"
#include "frontend/shots.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "render/camera.hpp"
#include "render/headless.hpp"
#include "render/image.hpp"
#include "render/png_band_writer.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::cli {
namespace {

// A reference mesh: its vertices and triangles.
struct Reference {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles;
  double diagonal = 0;
};

double diagonal_of(const std::vector<Point<3>>& points) {
  Point<3> low = points.front(), high = points.front();
  for (const auto& p : points) {
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  }
  return std::sqrt((high[0] - low[0]) * (high[0] - low[0]) +
                   (high[1] - low[1]) * (high[1] - low[1]) +
                   (high[2] - low[2]) * (high[2] - low[2]));
}

Reference read_reference(const std::string& path) {
  const frontend::Input mesh = frontend::load_input(path, "", 3);
  if (mesh.reference_triangles.empty()) {
    throw io::Error("the reference '" + path + "' has no triangles: it must be a mesh");
  }
  Reference reference;
  reference.points = std::get<std::vector<Point<3>>>(mesh.points);
  reference.triangles = mesh.reference_triangles;
  reference.diagonal = diagonal_of(reference.points);
  return reference;
}

// The reference of an input: the --reference mesh, or a mesh input's own triangles; none for
// curves and point files without one.
std::optional<Reference> reference_of(const frontend::Input& input,
                                      const std::optional<Reference>& given) {
  if (given && input.dimension() != 3) {
    throw frontend::Usage_error("--reference is a mesh of a surface; " + input.description +
                                " is 2D points");
  }
  if (input.dimension() != 3) return std::nullopt;
  if (given) return given;
  if (input.reference_triangles.empty()) return std::nullopt;
  Reference reference;
  reference.points = std::get<std::vector<Point<3>>>(input.points);
  reference.triangles = input.reference_triangles;
  reference.diagonal = diagonal_of(reference.points);
  return reference;
}

// The verdict in a table cell: what the result is (before the counts), or what is wrong, and
// the handles whose genus the samples cannot vouch for (suspect, refused), whichever it is; and
// how the samples were cleaned.
std::string short_verdict(const nlohmann::json& stats) {
  const std::string line = stats["verdict"];
  const bool defective = line.rfind("NOT", 0) == 0;
  std::string cell = line.substr(0, line.find(defective ? ';' : ':'));
  const auto handles = [](std::size_t n) {
    return fmt::format("{} handle{}", n, n == 1 ? "" : "s");
  };
  const std::size_t suspect = stats.value("thin_handles", std::size_t{0});
  const std::size_t refused = stats.value("refused_handles", std::size_t{0});
  if (suspect > 0) cell += "; " + handles(suspect) + " suspect";
  if (refused > 0) cell += "; " + handles(refused) + " refused";
  // What the surface does not pass through, or passes through moved.
  const std::size_t outliers = stats.value("outliers_removed", std::size_t{0});
  if (outliers > 0)
    cell += fmt::format("; {} outlier{} removed", outliers, outliers == 1 ? "" : "s");
  if (stats.value("smoothed", false)) cell += "; smoothed";
  return cell;
}

std::string number_or_dash(double value, const char* format) {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : std::string("—");
}

void paste(render::Image& canvas, const render::Image& tile, int left, int top) {
  for (int y = 0; y < tile.height; ++y) {
    std::copy_n(tile.pixel(0, y), 4 * tile.width,
                &canvas.rgba[4 * (std::size_t(top + y) * canvas.width + left)]);
  }
}

class Comparison {
 public:
  // `grid_path`, if given, receives the picture grid, a row of tiles per input, each row
  // written as soon as it is drawn: memory holds one row of tiles, whatever the inputs.
  Comparison(const Compare_arguments& args, std::string grid_path)
      : args_(args), grid_path_(std::move(grid_path)) {
    methods_ = args.inputs.methods;
    if (methods_.empty()) methods_.assign(method_names().begin(), method_names().end());
  }

  void run() {
    const auto inputs = bench_inputs(args_.inputs);
    if (!args_.reference.empty() && inputs.size() != 1) {
      throw frontend::Usage_error("--reference goes with one input, not " +
                                  std::to_string(inputs.size()));
    }
    if (!args_.reference.empty()) {
      given_reference_ = read_reference(args_.reference);
      // Before any measuring: a reference is a surface's, for 3D points.
      const auto& source = inputs.front().second;
      const bool example = source.front() == "--example";
      const frontend::Input input = frontend::load_input(
          example ? "" : source[1], example ? source[1] : "", 0, args_.inputs.merge_duplicates);
      reference_of(input, given_reference_);
    }
    Bench_arguments measuring = args_.inputs;
    measuring.advancing_front = false;  // the method advancing-front is CGAL's, measured as one
    // Every measuring process first, while this one is small; then the results again here.
    for (const auto& [name, source] : inputs) {
      nlohmann::json row = measure_input(name, source, measuring);
      if (row["delaunay_only"].contains("error")) {
        throw io::Error(name + ": " + row["delaunay_only"]["error"].get<std::string>());
      }
      for (auto& [method, s] : row["methods"].items()) {
        if (s.contains("error")) continue;
        // Interpolating methods: the result's vertices are the samples on it; the power crust
        // counts its own.
        const std::size_t own = s.value("surface_vertices", std::size_t{0});
        const std::size_t vertices =
            own > 0 ? own
                    : s["samples"].get<std::size_t>() - s["unused_samples"].get<std::size_t>();
        s["output_vertices"] = vertices;
        s["output_vertices_per_sample"] = double(vertices) / s["samples"].get<double>();
      }
      rows_.push_back(std::move(row));
      if (isatty(STDERR_FILENO)) std::cerr << "sculpt compare: " << name << " measured\n";
    }
    grid_rows_ = inputs.size();
    check_a_method_measured(methods_, rows_);
    check_a_method_succeeded();
    for (std::size_t k = 0; k < inputs.size(); ++k) measure_results(inputs[k].second, rows_[k]);
    if (grid_) grid_->finish();
  }

  std::string markdown() const {
    std::ostringstream out;
    out << "| input | n | method | seconds | × DT | MiB | × DT | vertices / n | verdict | border "
           "loops | non-manifold edges | pieces | Euler (mesh) | unused | reproduced | Hausdorff / "
           "diagonal |\n";
    out << "|---|--:|---|--:|--:|--:|--:|--:|---|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& row : rows_) {
      const auto& dt = row["delaunay_only"]["process"];
      const double dt_seconds = dt["cpu_seconds"], dt_mib = dt["peak_mib"];
      const auto reference = row["delaunay_only"].find("reference");
      for (const auto& method : methods_) {              // in the order asked
        if (!row["methods"].contains(method)) continue;  // not for this dimension
        const auto& s = row["methods"][method];
        const std::string input = row["input"];
        if (s.contains("error")) {
          out << fmt::format("| {} | {} | {} | failed: {} |||||||||||||\n", input,
                             row["samples"].get<std::size_t>(), method,
                             s["error"].get<std::string>());
          continue;
        }
        const double seconds = s["process"]["cpu_seconds"], mib = s["process"]["peak_mib"];
        const long euler = s["euler_characteristic"];
        out << fmt::format(
            "| {} | {} | {} | {:.3f} | {:.2f} | {:.0f} | {:.2f} | {:.3f} | {} | {} | {} | {} | {} "
            "| "
            "{} | {} | {} |\n",
            input, row["samples"].get<std::size_t>(), method, seconds, seconds / dt_seconds, mib,
            mib / dt_mib, s.value("output_vertices_per_sample", 0.0), short_verdict(s),
            s["boundary_loops"].get<std::size_t>(), s["non_manifold_ridges"].get<std::size_t>(),
            s["components"].get<std::size_t>(),
            reference != row["delaunay_only"].end()
                ? fmt::format("{} ({})", euler, (*reference)["euler_characteristic"].get<long>())
                : std::to_string(euler),
            s["unused_samples"].get<std::size_t>(),
            number_or_dash(s.value("reproduced", std::nan("")) * 100, "{:.1f}%"),
            number_or_dash(s.value("hausdorff_per_diagonal", std::nan("")), "{:.4f}"));
      }
    }
    out << "\nseconds, MiB: CPU time and peak memory of a process that reads the input and runs "
           "the method; × DT: against the process that builds CGAL's Delaunay triangulation of "
           "the same points, in the same run. vertices / n: the result's vertices per sample. "
           "Hausdorff: two-sided, to the reference mesh, over its bounding box's diagonal.\n";
    return out.str();
  }

  const std::vector<nlohmann::json>& rows() const { return rows_; }

 private:
  // A comparison in which every method failed on every input compares nothing: the run fails,
  // in the words of the first failure, inputs and methods in the order asked (the same input's
  // refusal, as `reconstruct` says it).
  void check_a_method_succeeded() const {
    std::string first;
    for (const auto& row : rows_) {
      for (const auto& method : methods_) {
        if (!row["methods"].contains(method)) continue;  // not for this dimension
        const auto& s = row["methods"][method];
        if (!s.contains("error")) return;
        if (first.empty())
          first = row["input"].get<std::string>() + ": " + s["error"].get<std::string>();
      }
    }
    if (!first.empty()) throw io::Error(first);
  }

  // The results again, in this process (untimed): their vertices, their distance to the
  // reference, and their pictures.
  void measure_results(const std::vector<std::string>& source, nlohmann::json& row) {
    const bool example = source.front() == "--example";
    const frontend::Input input = frontend::load_input(
        example ? "" : source[1], example ? source[1] : "", 0, args_.inputs.merge_duplicates);
    const std::optional<Reference> reference = reference_of(input, given_reference_);
    if (!reference && args_.pictures.empty()) return;  // nothing more to measure
    samples_only_.reset();                             // a new input
    tile_camera_ = nullptr;
    if (given_reference_ && reference) {
      const Statistics own = facet_topology(reference->points.size(), reference->triangles);
      row["delaunay_only"]["reference"] = {{"triangles", reference->triangles.size()},
                                           {"euler_characteristic", own.euler_characteristic},
                                           {"components", own.components},
                                           {"boundary_loops", own.boundary_loops}};
    }
    std::vector<render::Image> tiles;
    for (const auto& method : methods_) {
      frontend::Shot shot;
      shot.input = example ? "" : source[1];
      shot.example = example ? source[1] : "";
      shot.bordered = std::find(source.begin(), source.end(), "--bordered") != source.end();
      shot.closed = std::find(source.begin(), source.end(), "--closed") != source.end();
      shot.method = method;
      shot.stage = "surface";
      shot.size = args_.tile;
      if (!row["methods"].contains(method) || row["methods"][method].contains("error")) {
        shot.stage = "samples";  // the method does not apply here, or failed
        shot.title = method + ": " +
                     (row["methods"].contains(method)
                          ? "failed"
                          : "not for " + std::to_string(input.dimension()) + "D");
        shot.method = to_string(Options{}.method);
        tiles.push_back(draw(shot, input));
        continue;
      }
      auto& measured = row["methods"][method];
      Method parsed;
      parse_method(method, parsed);
      Options options;
      options.method = parsed;
      options.kind = frontend::kind_of(shot);  // as the timed job: an example's own, else chosen
      parse_cleaning(args_.inputs.cleaning, options.cleaning);  // checked by the command line
      const frontend::Any_reconstruction result = frontend::reconstruct_input(input, options);
      const Statistics& stats =
          std::visit([](const auto& r) -> const Statistics& { return r.stats; }, result);
      if (reference) {
        const auto& r = std::get<Reconstruction<3>>(result);
        const std::vector<Point<3>> samples(r.sites.begin(), r.sites.begin() + r.sample_count());
        const double distance =
            hausdorff_distance(r.interpolates() ? samples : r.surface_vertices, r.surface,
                               reference->points, reference->triangles);
        measured["hausdorff"] = std::isfinite(distance) ? nlohmann::json(distance) : nullptr;
        measured["hausdorff_per_diagonal"] =
            std::isfinite(distance) ? nlohmann::json(distance / reference->diagonal) : nullptr;
        // Same vertices, same order; a result with vertices of its own reproduces none.
        if (given_reference_ && reference->points == samples && r.interpolates()) {
          measured["reproduced"] = triangles_reproduced(reference->triangles, r.surface);
        }
      }
      // The table says what is wrong; a tile has room for whether anything is.
      shot.title = method + (verdict(stats).manifold ? ": manifold" : ": NOT manifold");
      // A manifold whose genus the carving held down is not simply right.
      if (stats.refused_handles > 0)
        shot.title += fmt::format(", {} refused", stats.refused_handles);
      if (stats.thin_handles > 0) shot.title += fmt::format(", {} suspect", stats.thin_handles);
      tiles.push_back(draw(shot, result));
    }
    if (!args_.pictures.empty()) add_grid_row(tiles);
  }

  // A tile of the grid; every tile of an input fits the same box, the samples', and is seen by
  // one camera: the first tile's, stepped back for its legend.
  render::Image draw(const frontend::Shot& shot, const frontend::Any_reconstruction& result) {
    if (args_.pictures.empty()) return {};
    if (!renderer_) renderer_ = std::make_unique<render::Headless_renderer>();
    frontend::Picture picture = frontend::draw_shot(
        *renderer_, shot, result, tile_camera_.is_null() ? nullptr : &tile_camera_);
    if (tile_camera_.is_null()) tile_camera_ = render::to_json(picture.camera);
    return std::move(picture.image);
  }
  // A tile of the samples alone, where a method does not apply: drawn from one reconstruction
  // per input, made only for them.
  render::Image draw(const frontend::Shot& shot, const frontend::Input& input) {
    if (args_.pictures.empty()) return {};
    if (!samples_only_) {
      Options options;
      options.keep_triangulations = false;
      samples_only_ = frontend::reconstruct_input(input, options);
    }
    return draw(shot, *samples_only_);
  }

  // Every tile has the size --tile asks; every row one tile per method.
  void add_grid_row(const std::vector<render::Image>& tiles) {
    const int width = tiles.front().width, height = tiles.front().height;
    if (!grid_) {
      grid_ = std::make_unique<render::Png_band_writer>(grid_path_, width * int(methods_.size()),
                                                        height * int(grid_rows_));
    }
    render::Image row;
    row.width = width * int(methods_.size());
    row.height = height;
    row.rgba.assign(4 * std::size_t(row.width) * row.height, 255);
    for (std::size_t k = 0; k < tiles.size(); ++k) paste(row, tiles[k], int(k) * width, 0);
    grid_->add(row);
  }

  const Compare_arguments& args_;
  std::vector<std::string> methods_;
  std::vector<nlohmann::json> rows_;
  std::optional<Reference> given_reference_;  // --reference
  std::unique_ptr<render::Headless_renderer> renderer_;
  std::optional<frontend::Any_reconstruction> samples_only_;  // this input's, for draw()
  nlohmann::json tile_camera_;  // this input's tiles' camera, once its first is drawn
  std::string grid_path_;
  std::size_t grid_rows_ = 0;
  std::unique_ptr<render::Png_band_writer> grid_;
};

void check_outputs(const Compare_arguments& args) {
  const auto check = [](const std::string& path, const char* extension, const char* what) {
    if (path.empty()) return;
    if (io::extension_of(path) != extension) {
      throw frontend::Usage_error(
          fmt::format("the {} must end in {}: '{}'", what, extension, path));
    }
  };
  check(args.markdown, ".md", "markdown table");
  check(args.json, ".json", "JSON table");
  check(args.pictures, ".png", "picture grid");
  // Before any work: every output can be written, and none is an input or the reference.
  std::vector<std::string> inputs = args.inputs.inputs;
  inputs.push_back(args.reference);
  io::check_destinations({args.markdown, args.json, args.pictures}, inputs);
  try {
    frontend::parse_size(args.tile);
  } catch (const io::Error& e) {
    throw frontend::Usage_error(e.what());
  }
  if (args.pictures.empty() && args.tile != Compare_arguments{}.tile) {
    throw frontend::Usage_error("--tile sizes the pictures of --pictures; there are none");
  }
}

}  // namespace

int run_compare(const Compare_arguments& args) {
  check_outputs(args);
  if (args.inputs.inputs.empty() && args.inputs.examples.empty()) {
    throw frontend::Usage_error("compare needs an input file or --example");
  }
  io::Output_set outputs;  // every file or none
  Comparison comparison(args, args.pictures.empty() ? "" : outputs.stage(args.pictures));
  comparison.run();
  const std::string table = comparison.markdown();
  if (!args.markdown.empty()) {
    io::Atomic_file file(outputs.stage(args.markdown), false);
    file.stream() << table;
    file.commit();
  }
  if (!args.json.empty()) {
    io::Atomic_file file(outputs.stage(args.json), false);
    file.stream() << nlohmann::json(comparison.rows()).dump(2) << '\n';
    file.commit();
  }
  outputs.commit();
  std::cout << table;
  return 0;
}

}  // namespace sculpt::cli
