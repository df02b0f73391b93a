// SPDX-License-Identifier: GPL-3.0-or-later
// The core as a WebAssembly module for JavaScript, in Node and in browsers (web/package/sculpt.mjs
// wraps these functions): reconstruct points with any method, read a point file with the command
// line's readers, and run the viewer's reconstruction requests in a Web Worker. A failure is the
// command line's one line (frontend/failure.hpp), never an abort.
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <sculpt/sculpt.hpp>
#include <string>
#include <variant>
#include <vector>

#include "frontend/failure.hpp"
#include "frontend/input.hpp"
#include "frontend/reconstruction_request.hpp"
#include "frontend/statistics_json.hpp"
#include "io/point_reader.hpp"
#include "io/reconstruction_bytes.hpp"

namespace {

// What a call leaves for JavaScript to read (through the accessors below) and then free.
struct Result {
  std::string error;  // empty on success
  std::string json;   // what the call says about its result
  std::vector<std::uint32_t> facets;
  std::vector<double> coordinates;
  std::vector<std::uint8_t> bytes;
};

// The progress of a run, handed to the JavaScript side: Module.onProgress(stage, fraction,
// overall) if it is set; it returns false to cancel.
// JavaScript below: clang-format would split its "===".
// clang-format off
EM_JS(int, report_progress, (const char* stage, double fraction, double overall), {
  const report = Module["onProgress"];
  if (!report) return 1;
  return report(UTF8ToString(stage), fraction, overall) === false ? 0 : 1;
});
// clang-format on

bool progress(const sculpt::Progress& p) {
  return report_progress(p.stage ? p.stage : "", p.fraction, p.overall) != 0;
}

// Options from JavaScript: {method, kind, rule, alpha, boxFactor}, each optional.
sculpt::Options options_from(const nlohmann::json& json) {
  sculpt::Options options;
  if (const auto method = json.value("method", std::string()); !method.empty()) {
    if (!sculpt::parse_method(method, options.method)) {
      std::string names;
      for (const char* name : sculpt::method_names())
        names += std::string(names.empty() ? "" : ", ") + name;
      throw sculpt::io::Error("no method '" + method + "' (methods: " + names + ")");
    }
  }
  if (const auto kind = json.value("kind", std::string()); !kind.empty()) {
    if (!sculpt::parse_kind(kind, options.kind))
      throw sculpt::io::Error("no kind '" + kind + "' (kinds: automatic, closed, bordered)");
  }
  if (const auto rule = json.value("rule", std::string()); !rule.empty()) {
    if (!sculpt::parse_rule(rule, options.rule))
      throw sculpt::io::Error("no surface rule '" + rule + "' (rules: auto, skin, extraction)");
  }
  if (const auto clean = json.value("clean", std::string()); !clean.empty()) {
    if (!sculpt::parse_cleaning(clean, options.cleaning))
      throw sculpt::io::Error("no cleaning '" + clean +
                              "' (cleanings: " + sculpt::cleaning_choices() + ")");
  }
  options.alpha = json.value("alpha", options.alpha);
  options.box_factor = json.value("boxFactor", options.box_factor);
  if (!(options.alpha >= 0) || !std::isfinite(options.alpha))
    throw sculpt::io::Error("alpha must be a length, or 0 for the smallest one solid");
  if (!(options.box_factor > 1) || !std::isfinite(options.box_factor))
    throw sculpt::io::Error("the box factor must be a number above 1");
  options.keep_triangulations = false;  // the command line's economy: only the result is read
  options.keep_solid = false;
  options.progress = progress;
  return options;
}

template <int D>
void keep_result(Result& result, const sculpt::Reconstruction<D>& r) {
  for (const auto& facet : r.surface)
    result.facets.insert(result.facets.end(), facet.begin(), facet.end());
  // The samples (the first sites; box corners and inserted poles follow them), or the
  // method's own vertices.
  const auto& points = r.surface_points();
  const std::size_t count = r.interpolates() ? r.sample_count() : points.size();
  for (std::size_t i = 0; i < count; ++i)
    result.coordinates.insert(result.coordinates.end(), points[i].begin(), points[i].end());
  const sculpt::Verdict verdict = sculpt::verdict(r.stats);
  nlohmann::json stats = sculpt::frontend::statistics_json(r.stats);
  stats["rule"] = sculpt::frontend::surface_rule_name(r.options, D);
  stats["box_factor"] = r.options.box_factor;
  result.json = nlohmann::json{
      {"dimension", D},
      {"interpolates", r.interpolates()},
      {"removedOutliers", r.removed_outliers},
      {"verdict", {{"manifold", verdict.manifold}, {"line", verdict.line}}},
      {"stats",
       stats}}.dump();
}

template <class Work>
Result* run(Work work) {
  auto* result = new Result;
  try {
    work(*result);
  } catch (const sculpt::Cancelled&) {
    result->error = "cancelled";
  } catch (const std::exception& e) {
    result->error = sculpt::frontend::failure_line(e);
  }
  return result;
}

}  // namespace

extern "C" {

// Reconstructs `count` points of `dimension` coordinates each.
EMSCRIPTEN_KEEPALIVE Result* sculpt_reconstruct(const double* coordinates, int count, int dimension,
                                                const char* options_json) {
  return run([&](Result& result) {
    if (dimension != 2 && dimension != 3)
      throw sculpt::io::Error("the dimension must be 2 or 3, not " + std::to_string(dimension));
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(options_json);
    } catch (const nlohmann::json::exception&) {
      throw sculpt::io::Error("the options are not an object of options");
    }
    const sculpt::Options options = options_from(json);
    const bool merge = json.value("mergeDuplicates", false);
    sculpt::io::Point_set set;
    set.dimension = dimension;
    for (int i = 0; i < count; ++i) {
      const double* p = coordinates + std::size_t(i) * dimension;
      set.points.push_back({p[0], p[1], dimension == 3 ? p[2] : 0.0});
    }
    if (merge) sculpt::io::merge_duplicates(set);
    if (dimension == 2) {
      keep_result(result, sculpt::reconstruct(sculpt::io::planar_points(set), options));
    } else {
      keep_result(result, sculpt::reconstruct(sculpt::io::spatial_points(set), options));
    }
  });
}

// Reads a point or mesh file of the module's file system with the command line's readers.
EMSCRIPTEN_KEEPALIVE Result* sculpt_read_points(const char* path, int forced_dimension,
                                                int merge_duplicates) {
  return run([&](Result& result) {
    const sculpt::frontend::Input input =
        sculpt::frontend::load_input(path, "", forced_dimension, merge_duplicates != 0);
    std::visit(
        [&](const auto& points) {
          for (const auto& p : points)
            result.coordinates.insert(result.coordinates.end(), p.begin(), p.end());
        },
        input.points);
    result.json =
        nlohmann::json{{"dimension", input.dimension()}, {"description", input.description}}.dump();
  });
}

// The viewer's request (frontend::Reconstruction_request as JSON): the reconstruction with
// every stage, as bytes (io/reconstruction_bytes.hpp), and the input's description. Its error is
// the bare message (the viewer says "error: " before it), as run_request gives it.
EMSCRIPTEN_KEEPALIVE Result* sculpt_run_request(const char* request_json) {
  auto* result = new Result;
  try {
    const auto request = sculpt::frontend::request_from_json(nlohmann::json::parse(request_json));
    sculpt::frontend::Reconstruction_outcome outcome =
        sculpt::frontend::run_request(request, progress);
    if (!outcome.error.empty()) {
      result->error = outcome.error;
      return result;
    }
    result->bytes =
        std::visit([](const auto& r) { return sculpt::io::to_bytes(r); }, *outcome.reconstruction);
    result->json = nlohmann::json{{"description", outcome.description}}.dump();
  } catch (const std::exception& e) {
    result->error = e.what();
  }
  return result;
}

EMSCRIPTEN_KEEPALIVE const char* sculpt_result_error(const Result* r) {
  return r->error.c_str();
}
EMSCRIPTEN_KEEPALIVE const char* sculpt_result_json(const Result* r) {
  return r->json.c_str();
}
EMSCRIPTEN_KEEPALIVE const std::uint32_t* sculpt_result_facets(const Result* r) {
  return r->facets.data();
}
EMSCRIPTEN_KEEPALIVE int sculpt_result_facet_indices(const Result* r) {
  return int(r->facets.size());
}
EMSCRIPTEN_KEEPALIVE const double* sculpt_result_coordinates(const Result* r) {
  return r->coordinates.data();
}
EMSCRIPTEN_KEEPALIVE int sculpt_result_coordinate_count(const Result* r) {
  return int(r->coordinates.size());
}
EMSCRIPTEN_KEEPALIVE const std::uint8_t* sculpt_result_bytes(const Result* r) {
  return r->bytes.data();
}
EMSCRIPTEN_KEEPALIVE int sculpt_result_byte_count(const Result* r) {
  return int(r->bytes.size());
}
EMSCRIPTEN_KEEPALIVE void sculpt_result_free(Result* r) {
  delete r;
}

// The methods: [{name, description, dimensions: [2, 3]}], the default first.
EMSCRIPTEN_KEEPALIVE const char* sculpt_methods() {
  static const std::string json = [] {
    nlohmann::json methods = nlohmann::json::array();
    for (const char* name : sculpt::method_names()) {
      sculpt::Method method;
      sculpt::parse_method(name, method);
      nlohmann::json dimensions = nlohmann::json::array();
      for (int d : {2, 3})
        if (sculpt::reconstructs_in(method, d)) dimensions.push_back(d);
      methods.push_back({{"name", name},
                         {"description", sculpt::describe(method)},
                         {"dimensions", dimensions},
                         {"interpolates", sculpt::interpolates(method)}});
    }
    return methods.dump();
  }();
  return json.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* sculpt_version() {
  return sculpt::version();
}

}  // extern "C"
