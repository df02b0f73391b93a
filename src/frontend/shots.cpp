// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/shots.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <type_traits>

#include "frontend/input.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "render/animation.hpp"
#include "render/camera.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::frontend {

namespace {

render::Camera camera_or_error(const nlohmann::json& json) {
  try {
    return render::camera_from_json(json);
  } catch (const std::invalid_argument& e) {
    throw io::Error(e.what());
  }
}

}  // namespace

std::pair<int, int> parse_size(const std::string& size) {
  int width = 0, height = 0;
  char x = 0;
  std::istringstream in(size);
  if (!(in >> width >> x >> height) || x != 'x' || width <= 0 || height <= 0 ||
      width > render::max_image_side || height > render::max_image_side) {
    throw io::Error("the size must be WIDTHxHEIGHT, each from 1 to " +
                    std::to_string(render::max_image_side) + " pixels, e.g. 800x600: '" + size +
                    "'");
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
  shot.closed = j.value("closed", false);
  shot.dimension = j.value("dimension", 0);
  shot.stage = j.value("stage", shot.stage);
  shot.step = j.value("step", -1L);
  shot.focus_sample = j.value("focus_sample", -1);
  shot.focus_pole = j.value("focus_pole", -1);
  shot.method = j.value("method", shot.method);
  shot.box_factor = j.value("box_factor", shot.box_factor);
  shot.alpha = j.value("alpha", shot.alpha);
  shot.merge_duplicates = j.value("merge_duplicates", false);
  shot.rule = j.value("rule", shot.rule);
  shot.layers = j.value("layers", std::vector<std::string>{});
  shot.clip = j.value("clip", "");
  shot.camera_file = j.value("camera_file", "");
  shot.save_camera = j.value("save_camera", "");
  shot.size = j.value("size", shot.size);
  shot.wireframe = j.value("wireframe", false);
  shot.smooth = j.value("smooth", false);
  shot.no_legend = !j.value("legend", true);
  shot.zoom = j.value("zoom", shot.zoom);
  shot.ball_every = j.value("ball_every", 1);
  shot.polar_balls = j.value("polar_balls", false);
  shot.neighbourhood = j.value("neighbourhood", false);
  shot.yaw = j.value("yaw", shot.yaw);
  shot.pitch = j.value("pitch", shot.pitch);
  shot.title = j.value("title", "");
  shot.animate = j.value("animate", "");
  shot.frames = j.value("frames", shot.frames);
  shot.frame_ms = j.value("frame_ms", shot.frame_ms);
  shot.output = j.value("output", "");
  return shot;
}

scene::Request request_of(const Shot& shot) {
  scene::Request request;
  if (!scene::parse_stage(shot.stage, request.stage)) {
    std::string stages;
    for (auto s : scene::all_stages())
      stages += std::string(stages.empty() ? "" : ", ") + scene::stage_id(s);
    throw io::Error("no stage '" + shot.stage + "' (stages: " + stages + ")");
  }
  if (shot.step < -1) {
    throw io::Error("the step must be an event count, or -1 for all: " + std::to_string(shot.step));
  }
  if (!(shot.zoom > 0) || !std::isfinite(shot.zoom)) {
    throw io::Error("the zoom must be a positive number (below 1 zooms in): " +
                    std::to_string(shot.zoom));
  }
  if (!std::isfinite(shot.yaw) || !std::isfinite(shot.pitch)) {
    throw io::Error("the camera's yaw and pitch must be finite angles (radians)");
  }
  if (shot.ball_every < 1) {
    throw io::Error("ball_every must be at least 1 (every k-th polar ball): " +
                    std::to_string(shot.ball_every));
  }
  if (!shot.clip.empty()) {
    char comma1 = 0, comma2 = 0;
    std::istringstream in(shot.clip);
    auto& c = request.clip;
    char comma3 = ',';
    const bool read = in >> c.position >> comma1 >> c.azimuth >> comma2 >> c.elevation &&
                      (!(in >> std::ws >> comma3) || (comma3 == ',' && in >> c.slab));
    if (!read || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
        !(c.position >= 0 && c.position <= 1) || !std::isfinite(c.azimuth) ||
        !std::isfinite(c.elevation) || !(c.slab >= 0 && c.slab <= 1)) {
      throw io::Error(
          "the clip must be POSITION,AZIMUTH,ELEVATION[,SLAB]: a position 0 to 1 "
          "across the samples' box, the plane's normal in degrees, a slab's "
          "thickness 0 to 1, e.g. 0.5,0,90: '" +
          shot.clip + "'");
    }
    request.clipped = true;
  }
  request.step = shot.step;
  request.focus_sample = shot.focus_sample;
  request.focus_pole = shot.focus_pole;
  request.ball_every = shot.ball_every;
  request.polar_balls = shot.polar_balls;
  if (shot.neighbourhood && shot.focus_sample < 0)
    throw io::Error("the neighbourhood view needs a picked sample (focus_sample)");
  request.neighbourhood = shot.neighbourhood;
  request.layers = shot.layers;
  request.wireframe = shot.wireframe;
  request.smooth = shot.smooth;
  return request;
}

Picture draw_shot(render::Picture_renderer& renderer, const Shot& shot,
                  const Any_reconstruction& reconstruction, const nlohmann::json* inline_camera) {
  const scene::Request request = request_of(shot);
  const auto [width, height] = parse_size(shot.size);

  Picture picture;
  try {
    picture.scene =
        std::visit([&](const auto& r) { return scene::build_scene(r, request); }, reconstruction);
  } catch (const std::invalid_argument& e) {
    throw io::Error(e.what());
  }
  if (!shot.title.empty()) picture.scene.title = shot.title;
  picture.camera =
      render::fit(picture.scene, float(width) / float(height), shot.zoom, shot.yaw, shot.pitch);
  if (inline_camera) picture.camera = camera_or_error(*inline_camera);
  if (!shot.camera_file.empty()) picture.camera = camera_or_error(read_json(shot.camera_file));
  render::Draw_options options;
  options.legend = options.title = !shot.no_legend;
  picture.image = renderer.render(picture.scene, picture.camera, width, height, options);
  return picture;
}

std::string output_format_problem(const Shot& shot) {
  if (shot.animate.empty()) {
    return io::extension_of(shot.output) == ".png"
               ? ""
               : "render writes PNG images: '" + shot.output + "' does not end in .png";
  }
  return io::extension_of(shot.output) == ".webp" ? ""
                                                  : "an animation is written as animated WebP: '" +
                                                        shot.output + "' does not end in .webp";
}

namespace {

// The pictures of an animation: the shot at each step of the replay, or at each stage.
std::vector<Shot> animation_frames(const Shot& shot, const Any_reconstruction& reconstruction) {
  std::vector<Shot> frames;
  std::visit(
      [&](const auto& r) {
        constexpr int D = std::decay_t<decltype(r)>::dimension;
        if (shot.animate == "stages") {
          for (scene::Stage stage : scene::stages_of(r.options.method, D)) {
            frames.push_back(shot);
            frames.back().stage = scene::stage_id(stage);
          }
          return;
        }
        if (!scene::has_stage(r.options.method, D, scene::Stage::propagation))
          throw io::Error(std::string("the method ") + to_string(r.options.method) +
                          " labels no poles: it has no replay (animate stages instead)");
        const long events = long(r.propagation.events.size());
        if (events == 0) throw io::Error("no pole was labelled: there is no replay to animate");
        const long count = std::clamp<long>(shot.frames, 2, events + 1);
        for (long k = 0; k < count; ++k) {
          frames.push_back(shot);
          frames.back().stage = scene::stage_id(scene::Stage::propagation);
          frames.back().step = (k * events + (count - 1) / 2) / (count - 1);
        }
      },
      reconstruction);
  return frames;
}

}  // namespace

void check_shot(const Shot& shot) {
  if (shot.output.empty()) throw io::Error("a shot has no output file");
  const bool animated = !shot.animate.empty();
  if (animated && shot.animate != "replay" && shot.animate != "stages")
    throw io::Error("an animation is a replay or a sweep of the stages, not '" + shot.animate +
                    "'");
  if (animated &&
      (shot.frames < 2 || shot.frames > 2000 || shot.frame_ms < 0 || shot.frame_ms > 60000))
    throw io::Error("an animation has 2 to 2000 frames, each shown 0 ms (automatic) to 60,000 ms");
  if (const std::string problem = output_format_problem(shot); !problem.empty())
    throw io::Error(problem);
  // Before any work: the picture and the camera can be written, and neither is an input.
  io::check_destinations({shot.output, shot.save_camera}, {shot.input, shot.camera_file});
  request_of(shot);  // an unknown stage or size fails before any work
  parse_size(shot.size);
}

scene::Scene write_shot(render::Picture_renderer& renderer, const Shot& shot,
                        const Any_reconstruction& shown, const nlohmann::json* inline_camera) {
  check_shot(shot);
  if (!shot.animate.empty()) {
    std::vector<render::Image> images;
    scene::Scene last;
    // The replay follows the pole just labelled, as the viewer does (render::follow_point),
    // from the first picture's camera.
    std::optional<render::Camera> camera;
    glm::vec3 lower{}, upper{};  // the samples' box
    bool framed_far = false;     // the camera frames a far pole with the shape
    const auto [width, height] = parse_size(shot.size);
    for (const Shot& frame : animation_frames(shot, shown)) {
      nlohmann::json followed;
      if (camera && shot.animate == "replay" && frame.step > 0) {
        const glm::vec3 pole = std::visit(
            [&](const auto& r) {
              return render::to_glm(
                  r.poles.poles[r.propagation.events[frame.step - 1].pole].center);
            },
            shown);
        const render::Follow moved = render::follow_point(*camera, pole, lower, upper,
                                                          float(width) / float(height), framed_far);
        framed_far =
            moved == render::Follow::framed_far || (framed_far && moved == render::Follow::stayed);
        followed = render::to_json(*camera);
      }
      Picture picture =
          draw_shot(renderer, frame, shown, followed.is_null() ? inline_camera : &followed);
      if (!camera) {
        camera = picture.camera;
        lower = render::to_glm(picture.scene.lower);
        upper = render::to_glm(picture.scene.upper);
      }
      images.push_back(std::move(picture.image));
      last = std::move(picture.scene);
    }
    const int milliseconds = shot.frame_ms > 0          ? shot.frame_ms
                             : shot.animate == "replay" ? 80
                                                        : 1200;
    try {
      render::write_animation(shot.output, images, milliseconds);
    } catch (const std::runtime_error& e) {
      throw io::Error(e.what());
    }
    return last;
  }
  Picture picture = draw_shot(renderer, shot, shown, inline_camera);
  if (!shot.save_camera.empty()) {
    io::Atomic_file file(shot.save_camera, false);
    file.stream() << render::to_json(picture.camera).dump(2) << '\n';
    file.commit();
  }
  render::write_png(shot.output, picture.image);
  return std::move(picture.scene);
}

}  // namespace sculpt::frontend
