// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/option_use.hpp"

#include <algorithm>

#include "core/stage_plan.hpp"
#include "io/point_reader.hpp"

namespace sculpt::frontend {
namespace {

// An option's name where the user wrote it: "--box-factor", "box_factor=", "\"box_factor\"".
std::string named(const char* flag, const char* keyword, Spelling spelling) {
  switch (spelling) {
    case Spelling::command_line:
      return flag;
    case Spelling::python:
      return std::string(keyword) + "=";
    case Spelling::shots_file:
      return std::string("\"") + keyword + "\"";
  }
  return flag;
}

std::string methods_that(bool (*reads)(Method)) {
  std::string names;
  for (const char* name : method_names()) {
    Method method;
    parse_method(name, method);
    if (reads(method)) names += (names.empty() ? "" : ", ") + std::string(name);
  }
  return names;
}

// The methods that label poles from seeds and so read a bordered surface's seed sample
// (core/seeds.hpp): the sculpting methods and the power crust.
bool labels_from_seeds(Method method) {
  return sculpts(method) || method == Method::power_crust;
}

// The rule of surface extraction: the paper's, and the robust method's wherever it inserts
// poles as the paper does (a bordered 3D surface; the automatic kind may try one).
bool reads_rule(const Options& options) {
  return options.method == Method::paper ||
         (options.method == Method::robust && options.kind != Surface_kind::closed);
}

}  // namespace

std::string unused_reconstruction_option(const Options& options, Spelling spelling) {
  const Options defaults;
  const std::string method = to_string(options.method);
  if (options.alpha != defaults.alpha && options.method != Method::alpha_shape) {
    return named("--alpha", "alpha", spelling) +
           " is the radius of the method alpha-shape; the method " + method + " has none";
  }
  if (options.rule != defaults.rule && !reads_rule(options)) {
    return named("--rule", "rule", spelling) +
           " chooses the facets of the surface after the paper's pole insertion (paper, and "
           "robust on a bordered surface); the method " +
           method + (options.method == Method::robust ? " carves a closed one" : " has its own");
  }
  if (options.bordered_seed_sample != defaults.bordered_seed_sample) {
    if (!labels_from_seeds(options.method)) {
      return named("--seed-sample", "bordered_seed_sample", spelling) + " seeds the labelling of " +
             methods_that(labels_from_seeds) + " on a bordered surface; the method " + method +
             " labels no poles from a seed";
    }
    // A method that does not choose the kind reconstructs an automatic one as closed.
    if (options.kind == Surface_kind::closed ||
        (options.kind == Surface_kind::automatic && !chooses_kind(options.method))) {
      return named("--seed-sample", "bordered_seed_sample", spelling) +
             " seeds a bordered surface (" + named("--bordered", "kind='bordered'", spelling) +
             "); a closed one starts from every convex pole";
    }
  }
  // The box is DT(S ∪ BBV)'s: CGAL's methods build it only when the triangulations are kept
  // (for the pictures of the shared stages), core/stage_plan.hpp.
  if (options.box_factor != defaults.box_factor && !builds_shared_stages(options)) {
    return named("--box-factor", "box_factor", spelling) +
           " sizes the bounding box of DT(S ∪ BBV); the method " + method +
           " triangulates the samples alone";
  }
  return "";
}

std::string unused_input_option(const std::string& example, int dimension, bool merge_duplicates,
                                Spelling spelling) {
  if (example.empty()) return "";
  if (dimension != 0) {
    return named("--dim", "dimension", spelling) + " reads a point file as 2D or 3D; the example " +
           example + " has its own dimension";
  }
  if (merge_duplicates) {
    return named("--merge-duplicates", "merge_duplicates", spelling) +
           " drops a point file's repeated points; the example " + example + " has none";
  }
  return "";
}

std::string unused_automatic_kind(Method method, Spelling spelling) {
  if (chooses_kind(method)) return "";
  return named("--automatic", "kind='automatic'", spelling) + ": only " +
         methods_that(chooses_kind) + " chooses the kind; the method " + to_string(method) +
         " reconstructs what it is told (" + named("--closed", "kind='closed'", spelling) + " or " +
         named("--bordered", "kind='bordered'", spelling) + ")";
}

std::string unused_ascii(const std::string& output, Spelling spelling) {
  const std::string extension = io::extension_of(output);
  if (extension == ".stl" || extension == ".ply") return "";
  return named("--ascii", "ascii", spelling) + " writes .stl and .ply as text; '" + output +
         "' is text already";
}

std::string unused_drawing_option(const Shot& shot, const scene::Scene& scene, Spelling spelling) {
  const Shot defaults;
  const auto has_layer = [&](const char* id) {
    return std::any_of(scene.layers.begin(), scene.layers.end(),
                       [&](const scene::Layer& layer) { return layer.id == id; });
  };
  // A section draws what the plane cuts, flat: what picks, thins or shades does not apply.
  if (!shot.section.empty()) {
    const std::pair<bool, std::pair<const char*, const char*>> flat[] = {
        {shot.focus_sample != defaults.focus_sample, {"--focus-sample", "focus_sample"}},
        {shot.focus_pole != defaults.focus_pole, {"--focus-pole", "focus_pole"}},
        {shot.neighbourhood, {"--neighbourhood", "neighbourhood"}},
        {shot.wireframe, {"--wireframe", "wireframe"}},
        {shot.smooth, {"--smooth", "smooth"}},
        {shot.ball_opacity != defaults.ball_opacity, {"--ball-opacity", "ball_opacity"}},
    };
    for (const auto& [given, names] : flat) {
      if (given)
        return named(names.first, names.second, spelling) +
               " does not apply to a section, which draws the cut in the plane (" +
               named("--clip", "clip", spelling) + " cuts away instead)";
    }
  }
  if (scene::Stage stage; shot.step != defaults.step &&
                          !(scene::parse_stage(shot.stage, stage) && scene::replays(stage))) {
    return named("--step", "step", spelling) +
           " chooses a moment of a replay, at the stages propagation, carving, candidates, front "
           "and alpha; "
           "this is the stage " +
           shot.stage;
  }
  if ((shot.smooth && !has_layer("surface")) ||
      (shot.wireframe && !has_layer("surface") && !has_layer("wireframe"))) {
    return named(shot.wireframe ? "--wireframe" : "--smooth",
                 shot.wireframe ? "wireframe" : "smooth", spelling) +
           " draws a reconstructed surface, at the stage surface of 3D points; this picture "
           "has none";
  }
  const bool balls =
      has_layer("polar-balls") || has_layer("inner-balls") || has_layer("outer-balls");
  if ((shot.ball_limit != defaults.ball_limit || shot.ball_opacity != defaults.ball_opacity) &&
      !balls) {
    const bool limit = shot.ball_limit != defaults.ball_limit;
    return named(limit ? "--ball-limit" : "--ball-opacity", limit ? "ball_limit" : "ball_opacity",
                 spelling) +
           " applies to the polar balls; this picture draws none (" +
           named("--polar-balls", "polar_balls", spelling) + " draws them at any stage)";
  }
  if (shot.ball_every != defaults.ball_every && !balls) {
    return named("--ball-every", "ball_every", spelling) +
           " thins the polar balls; this picture draws none (" +
           named("--polar-balls", "polar_balls", spelling) + " draws them at any stage)";
  }
  if (scene.dimension == 2 && (shot.yaw != defaults.yaw || shot.pitch != defaults.pitch)) {
    return named("--yaw", shot.yaw != defaults.yaw ? "yaw" : "pitch", spelling) +
           " turns a 3D camera; this picture is of a 2D curve";
  }
  return "";
}

std::string unused_animation_option(const Shot& shot, Spelling spelling) {
  const Shot defaults;
  if (shot.animate.empty()) {
    if (shot.frames != defaults.frames || shot.frame_ms != defaults.frame_ms) {
      return named(shot.frames != defaults.frames ? "--frames" : "--frame-ms",
                   shot.frames != defaults.frames ? "frames" : "frame_ms", spelling) +
             " times an animation (" + named("--animate", "animate", spelling) +
             " replay or stages); this is one picture";
    }
    return "";
  }
  // A replay's stage says which replay: the labelling's (propagation) or the carving's.
  scene::Stage stage;
  const bool replay_stage =
      shot.animate == "replay" && scene::parse_stage(shot.stage, stage) && scene::replays(stage);
  if ((shot.stage != defaults.stage && !replay_stage) || shot.step != defaults.step) {
    return named(shot.stage != defaults.stage && !replay_stage ? "--stage" : "--step",
                 shot.stage != defaults.stage && !replay_stage ? "stage" : "step", spelling) +
           " chooses one picture; an animation " +
           (shot.animate == "replay" ? "replays the labelling (or, with the stage carving, "
                                       "candidates, front or alpha, that stage) "
                                       "step by step"
                                     : "draws every stage in order");
  }
  if (shot.animate == "stages" && shot.frames != defaults.frames) {
    return named("--frames", "frames", spelling) +
           " counts a replay's pictures; an animation of the stages has one per stage";
  }
  return "";
}

}  // namespace sculpt::frontend
