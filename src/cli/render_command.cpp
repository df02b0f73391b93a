// SPDX-License-Identifier: GPL-3.0-or-later
#include "render_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "frontend/command_line.hpp"
#include "frontend/shot_renderer.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "scene/scene.hpp"

namespace sculpt::cli {
namespace {

// Every stage's name, in order; each method has some of them (scene::stages_of).
std::string stages_help() {
  std::string help;
  for (scene::Stage stage : scene::all_stages())
    help += (help.empty() ? "" : ", ") + std::string(scene::stage_id(stage));
  return help + " (each method has some; asking for one it lacks lists its own)";
}

}  // namespace
void add_render_command(CLI::App& app, Render_arguments& args) {
  Shot& shot = args.shot;
  auto* render = app.add_subcommand(
      "render", "Render a stage of the algorithm to PNG, headless (OSMesa, llvmpipe)");
  args.command = render;
  auto* input = render->add_option("input", shot.input, "Point file");
  auto* example = render->add_option("--example", shot.example, "A built-in example instead");
  input->excludes(example);
  render->add_option("--stage", shot.stage, stages_help())->capture_default_str();
  render->add_option("--step", shot.step,
                     "A replay (the stages propagation, carving, candidates, front, alpha): show "
                     "it after K events "
                     "or steps");
  render->add_option("--focus-sample", shot.focus_sample,
                     "Show this sample's Voronoi cell, poles, polar balls and inscribed cubes");
  render
      ->add_option("--ball-every", shot.ball_every,
                   "Polar balls of every k-th pole only (with the layer polar-balls)")
      ->check(CLI::PositiveNumber);
  render->add_flag("--polar-balls", shot.polar_balls,
                   "3D: also draw the polar balls (every --ball-every-th), at any stage");
  render
      ->add_option(
          "--ball-limit", shot.ball_limit,
          "3D: at most this many inner and this many outer polar balls, evenly picked (0: all)")
      ->check(CLI::NonNegativeNumber);
  render
      ->add_option("--ball-opacity", shot.ball_opacity,
                   "3D: the polar balls' opacity, above 0 and at most 1")
      ->capture_default_str();
  render->add_flag("--neighbourhood", shot.neighbourhood,
                   "Only the cells, faces and balls near the --focus-sample");
  render->add_option("--focus-pole", shot.focus_pole,
                     "Show this pole's polar ball and the pole that labelled it");
  render->add_option("--method", shot.method, frontend::methods_help())
      ->capture_default_str()
      ->check(CLI::IsMember(sculpt::method_names()));
  render->add_option("--box-factor", shot.box_factor, "Bounding box factor")->capture_default_str();
  render->add_option("--alpha", shot.alpha, "alpha-shape: the radius (default: chosen)")
      ->check(frontend::positive_length());
  render->add_option("--rule", shot.rule, "Surface rule: auto, skin or extraction")
      ->check(CLI::IsMember({"auto", "skin", "extraction"}));
  render
      ->add_option("--clean", shot.clean,
                   "Clean the samples first (3D): auto, none, outliers, jet or outliers+jet (as "
                   "reconstruct's); the samples stage then shows them as given, the outliers "
                   "removed and where smoothing moved them")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "none", "outliers", "jet", "outliers+jet"}));
  render->add_option("--layers", shot.layers, "Only these layers (comma separated)")
      ->delimiter(',');
  render
      ->add_option("--palette", shot.palette,
                   "Colours: paper (the paper's) or colour-blind (every pair of layers apart "
                   "with deuteranopia and protanopia too)")
      ->capture_default_str()
      ->check(CLI::IsMember({"paper", "colour-blind", "color-blind"}));
  render->add_option("--section", shot.section,
                     "3D: a true section at a plane, POSITION,AZIMUTH,ELEVATION (as --clip): the "
                     "cells it cuts as polygons filled by what they are, the Voronoi faces and "
                     "the surface where it crosses them, the samples near it; seen along the "
                     "plane's normal");
  render->add_option("--clip", shot.clip,
                     "3D: cut away what lies beyond a plane, POSITION,AZIMUTH,ELEVATION[,SLAB] (0 "
                     "to 1 across the samples' box along the normal; the normal's angles in "
                     "degrees; a slab's thickness as a share of the box), e.g. 0.5,0,90 shows "
                     "the lower half");
  render->add_option("--camera", shot.camera_file, "Camera JSON (default: fit the samples)");
  render->add_option("--save-camera", shot.save_camera, "Write the camera used as JSON");
  render->add_option("--size", shot.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_flag("--bordered", shot.bordered,
                   "Reconstruct a bordered surface (otherwise an example is reconstructed as its "
                   "own kind, and a file as its samples show)");
  render
      ->add_flag("--closed", shot.closed,
                 "Reconstruct a closed surface, also from a bordered example")
      ->excludes("--bordered");
  render->add_flag("--merge-duplicates", shot.merge_duplicates,
                   "Drop the file's repeated points instead of refusing it");
  render->add_option("--dim", shot.dimension, "Force 2 or 3 dimensions")
      ->check(CLI::IsMember({2, 3}));
  render->add_flag("--wireframe", shot.wireframe, "Surface: draw its edges");
  render->add_flag("--smooth", shot.smooth, "Surface: smooth shading");
  render->add_flag("--no-legend", shot.no_legend, "No legend and title");
  render
      ->add_option(
          "--animate", shot.animate,
          "An animated WebP instead of a PNG: 'replay' (the labelling, event by event; "
          "with --stage carving, candidates, front or alpha, that stage step by step) or 'stages' "
          "(the method's stages in order)")
      ->check(CLI::IsMember({"replay", "stages"}));
  render->add_option("--frames", shot.frames, "Pictures in a replay animation")
      ->check(CLI::Range(2, 2000))
      ->capture_default_str();
  render
      ->add_option("--frame-ms", shot.frame_ms,
                   "How long each picture shows, in ms (0: 80 a replay's, 1200 a stage's)")
      ->check(CLI::Range(0, 60000));
  auto* output = render->add_option("-o,--output", shot.output, "PNG file");
  render
      ->add_option("--shots", args.shots_file,
                   "Render a list of shots in one process: JSON {\"shots\": [{\"example\": "
                   "\"star\", \"stage\": \"poles\", \"output\": \"a.png\", ...}]}")
      ->excludes(output);  // each shot names its own output
}

namespace {

// Draws every shot, each picture (and camera) under a temporary name, and renames them into
// place together: every file of the list, or none. All are checked before the first is drawn.
void render_all(frontend::Shot_renderer& renderer, const std::vector<Shot>& shots,
                const std::vector<const nlohmann::json*>& cameras, const std::string& shots_file) {
  const auto spelling =
      shots_file.empty() ? frontend::Spelling::command_line : frontend::Spelling::shots_file;
  std::vector<std::string> outputs, inputs{shots_file};
  for (const Shot& shot : shots) {
    frontend::check_shot(shot);
    frontend::Shot_renderer::check_options(shot, spelling);
    outputs.insert(outputs.end(), {shot.output, shot.save_camera});
    inputs.insert(inputs.end(), {shot.input, shot.camera_file});
  }
  io::check_destinations(outputs, inputs);
  io::Output_set written;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    Shot staged = shots[i];
    staged.output = written.stage(shots[i].output);
    if (!staged.save_camera.empty()) staged.save_camera = written.stage(shots[i].save_camera);
    renderer.render(staged, cameras[i], spelling);
  }
  written.commit();
}

}  // namespace

int run_render(const Render_arguments& args) {
  frontend::Shot_renderer renderer;
  if (args.shots_file.empty()) {
    if (args.shot.output.empty())
      throw frontend::Usage_error(
          "render needs -o FILE.png (FILE.webp or FILE.gif with --animate)");
    // A usage error here, before any work (Shot_renderer checks the same for --shots lists).
    if (const std::string problem = frontend::output_format_problem(args.shot); !problem.empty())
      throw frontend::Usage_error(problem);
    render_all(renderer, {args.shot}, {nullptr}, "");
    return 0;
  }
  // Each shot of the list says all it asks: an option given beside --shots would be ignored.
  for (const CLI::Option* option : args.command->get_options()) {
    if (option->count() > 0 && option->get_name() != "--shots") {
      throw frontend::Usage_error(option->get_name() +
                                  " does not apply with --shots: each shot gives its own (put "
                                  "it in the shots file)");
    }
  }
  const nlohmann::json list = frontend::read_json(args.shots_file);
  if (!list.contains("shots") || !list["shots"].is_array()) {
    throw io::Error("'" + args.shots_file + "' has no \"shots\" list");
  }
  std::vector<Shot> shots;
  std::vector<const nlohmann::json*> cameras;
  for (const auto& entry : list["shots"]) {
    shots.push_back(frontend::shot_from_json(entry, "shot " + std::to_string(shots.size() + 1)));
    cameras.push_back(entry.contains("camera") ? &entry["camera"] : nullptr);
  }
  render_all(renderer, shots, cameras, args.shots_file);
  for (const Shot& shot : shots) std::cout << "wrote " << shot.output << '\n';
  return 0;
}

}  // namespace sculpt::cli
