#include "render_command.hpp"

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <variant>

#include "frontend/input.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "render/headless.hpp"

namespace sculpt::cli {
namespace {

using Any_reconstruction = std::variant<Reconstruction<2>, Reconstruction<3>>;

std::pair<int, int> parse_size(const std::string& size) {
  int width = 0, height = 0;
  char x = 0;
  std::istringstream in(size);
  if (!(in >> width >> x >> height) || x != 'x' || width <= 0 || height <= 0 || width > 16384 ||
      height > 16384) {
    throw io::Error("the size must be WIDTHxHEIGHT, e.g. 800x600: '" + size + "'");
  }
  return {width, height};
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::Error("cannot open '" + path + "'");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    throw io::Error("'" + path + "' is not valid JSON");
  }
}

Shot shot_from_json(const nlohmann::json& j) {
  Shot shot;
  shot.input = j.value("input", "");
  shot.example = j.value("example", "");
  shot.bordered = j.value("bordered", false);
  shot.dimension = j.value("dimension", 0);
  shot.stage = j.value("stage", shot.stage);
  shot.step = j.value("step", -1L);
  shot.focus_sample = j.value("focus_sample", -1);
  shot.focus_pole = j.value("focus_pole", -1);
  shot.box_factor = j.value("box_factor", 5.0);
  shot.rule = j.value("rule", shot.rule);
  shot.layers = j.value("layers", std::vector<std::string>{});
  shot.camera_file = j.value("camera_file", "");
  shot.save_camera = j.value("save_camera", "");
  shot.size = j.value("size", shot.size);
  shot.wireframe = j.value("wireframe", false);
  shot.smooth = j.value("smooth", false);
  shot.no_legend = !j.value("legend", true);
  shot.output = j.value("output", "");
  return shot;
}

// Renders shots, reconstructing each input once however many shots show it.
class Shot_renderer {
 public:
  void render(const Shot& shot, const nlohmann::json* inline_camera) {
    if (shot.output.empty()) throw io::Error("a shot has no output file");
    if (shot.input.empty() == shot.example.empty()) {
      throw io::Error("a shot needs an input file or an example (one of them)");
    }
    scene::Request request;
    if (!scene::parse_stage(shot.stage, request.stage)) {
      std::string stages;
      for (auto s : scene::all_stages())
        stages += std::string(stages.empty() ? "" : ", ") + scene::stage_id(s);
      throw io::Error("no stage '" + shot.stage + "' (stages: " + stages + ")");
    }
    request.step = shot.step;
    request.focus_sample = shot.focus_sample;
    request.focus_pole = shot.focus_pole;
    request.layers = shot.layers;
    request.wireframe = shot.wireframe;
    request.smooth = shot.smooth;
    const auto [width, height] = parse_size(shot.size);

    scene::Scene scene;
    try {
      scene = std::visit([&](const auto& r) { return scene::build_scene(r, request); },
                         reconstruction(shot));
    } catch (const std::invalid_argument& e) {
      throw io::Error(e.what());
    }
    render::Camera camera = render::fit(scene, float(width) / float(height));
    if (inline_camera) camera = camera_or_error(*inline_camera);
    if (!shot.camera_file.empty()) camera = camera_or_error(read_json(shot.camera_file));
    if (!shot.save_camera.empty()) {
      io::Atomic_file file(shot.save_camera, false);
      file.stream() << render::to_json(camera).dump(2) << '\n';
      file.commit();
    }
    if (!renderer_) renderer_ = std::make_unique<render::Headless_renderer>();
    render::Draw_options options;
    options.legend = options.title = !shot.no_legend;
    render::write_png(shot.output, renderer_->render(scene, camera, width, height, options));
  }

 private:
  static render::Camera camera_or_error(const nlohmann::json& json) {
    try {
      return render::camera_from_json(json);
    } catch (const std::invalid_argument& e) {
      throw io::Error(e.what());
    }
  }

  const Any_reconstruction& reconstruction(const Shot& shot) {
    const std::string key = shot.input + "|" + shot.example + "|" + std::to_string(shot.bordered) +
                            "|" + std::to_string(shot.dimension) + "|" +
                            std::to_string(shot.box_factor) + "|" + shot.rule;
    auto found = cache_.find(key);
    if (found != cache_.end()) return found->second;
    const frontend::Input input = frontend::load_input(shot.input, shot.example, shot.dimension);
    Options options;
    options.kind = shot.bordered ? Surface_kind::bordered : Surface_kind::closed;
    options.box_factor = shot.box_factor;
    options.rule = shot.rule == "skin"         ? Surface_rule::skin
                   : shot.rule == "extraction" ? Surface_rule::extraction
                                               : Surface_rule::automatic;
    Any_reconstruction result = std::visit(
        [&](const auto& points) -> Any_reconstruction { return reconstruct(points, options); },
        input.points);
    return cache_.emplace(key, std::move(result)).first->second;
  }

  std::map<std::string, Any_reconstruction> cache_;
  std::unique_ptr<render::Headless_renderer> renderer_;
};

}  // namespace

void add_render_command(CLI::App& app, Render_arguments& args) {
  Shot& shot = args.shot;
  auto* render = app.add_subcommand(
      "render", "Render a stage of the algorithm to PNG, headless (OSMesa, llvmpipe)");
  auto* input = render->add_option("input", shot.input, "Point file");
  auto* example = render->add_option("--example", shot.example, "A built-in example instead");
  input->excludes(example);
  render
      ->add_option("--stage", shot.stage,
                   "samples, delaunay, voronoi, poles, seeds, propagation, outer-concave, "
                   "sculpted-delaunay, solid, surface")
      ->capture_default_str();
  render->add_option("--step", shot.step, "Propagation: show the first K labelling events");
  render->add_option("--focus-sample", shot.focus_sample,
                     "Show this sample's Voronoi cell, poles, polar balls and inscribed cubes");
  render->add_option("--focus-pole", shot.focus_pole,
                     "Show this pole's polar ball and the pole that labelled it");
  render->add_option("--box-factor", shot.box_factor, "Bounding box factor")->capture_default_str();
  render->add_option("--rule", shot.rule, "Surface rule: auto, skin or extraction")
      ->check(CLI::IsMember({"auto", "skin", "extraction"}));
  render->add_option("--layers", shot.layers, "Only these layers (comma separated)")
      ->delimiter(',');
  render->add_option("--camera", shot.camera_file, "Camera JSON (default: fit the samples)");
  render->add_option("--save-camera", shot.save_camera, "Write the camera used as JSON");
  render->add_option("--size", shot.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_flag("--bordered", shot.bordered, "Reconstruct a bordered surface");
  render->add_option("--dim", shot.dimension, "Force 2 or 3 dimensions")
      ->check(CLI::IsMember({2, 3}));
  render->add_flag("--wireframe", shot.wireframe, "Surface: draw its edges");
  render->add_flag("--smooth", shot.smooth, "Surface: smooth shading");
  render->add_flag("--no-legend", shot.no_legend, "No legend and title");
  render->add_option("-o,--output", shot.output, "PNG file");
  render->add_option("--shots", args.shots_file,
                     "Render a list of shots in one process: JSON {\"shots\": [{\"example\": "
                     "\"star\", \"stage\": \"poles\", \"output\": \"a.png\", ...}]}");
}

int run_render(const Render_arguments& args) {
  Shot_renderer renderer;
  if (args.shots_file.empty()) {
    renderer.render(args.shot, nullptr);
    return 0;
  }
  const nlohmann::json list = read_json(args.shots_file);
  if (!list.contains("shots") || !list["shots"].is_array()) {
    throw io::Error("'" + args.shots_file + "' has no \"shots\" list");
  }
  for (const auto& entry : list["shots"]) {
    const Shot shot = shot_from_json(entry);
    const nlohmann::json* camera = entry.contains("camera") ? &entry["camera"] : nullptr;
    renderer.render(shot, camera);
    std::cerr << "sculpt render: wrote " << shot.output << '\n';
  }
  return 0;
}

}  // namespace sculpt::cli
