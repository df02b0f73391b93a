// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/shots.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <tuple>
#if defined(__GLIBC__)  // set by the C library's headers above
#include <malloc.h>
#endif

#include "frontend/input.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "render/animation.hpp"
#include "render/camera.hpp"
#include "render/legend_layout.hpp"
#include "scene/carving_replay.hpp"
#include "scene/clipping.hpp"
#include "scene/colours.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::frontend {

namespace {

// A camera given for a scene must be one of its dimension: a 3D camera on a curve would draw it
// in perspective, a 2D one a surface from straight above.
render::Camera camera_or_error(const nlohmann::json& json, const scene::Scene& scene,
                               const std::string& source) {
  render::Camera camera;
  try {
    camera = render::camera_from_json(json);
  } catch (const std::invalid_argument& e) {
    throw io::Error(e.what());
  }
  if (camera.dimension != scene.dimension) {
    throw io::Error(source + " is a " + std::to_string(camera.dimension) +
                    "D camera; this picture is of " + std::to_string(scene.dimension) + "D points");
  }
  return camera;
}

void save_camera(const render::Camera& camera, const std::string& path) {
  io::Atomic_file file(path, false);
  file.stream() << render::to_json(camera).dump(2) << '\n';
  file.commit();
}

}  // namespace

std::pair<int, int> parse_size(const std::string& size) {
  int width = 0, height = 0;
  char x = 0;
  std::istringstream in(size);
  if (!(in >> width >> x >> height) || x != 'x' || !(in >> std::ws).eof() || width <= 0 ||
      height <= 0 || width > render::max_image_side || height > render::max_image_side) {
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

namespace {

// "POSITION,AZIMUTH,ELEVATION[,SLAB]": a plane across the samples' box (scene::Clip).
scene::Clip plane_from_text(const std::string& text, const char* name, bool slab) {
  scene::Clip c;
  char comma1 = 0, comma2 = 0, comma3 = ',';
  std::istringstream in(text);
  const bool read = in >> c.position >> comma1 >> c.azimuth >> comma2 >> c.elevation &&
                    (!(in >> std::ws >> comma3) || (slab && comma3 == ',' && in >> c.slab));
  if (!read || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !(c.position >= 0 && c.position <= 1) || !std::isfinite(c.azimuth) ||
      !std::isfinite(c.elevation) || !(c.slab >= 0 && c.slab <= 1)) {
    throw io::Error(std::string("the ") + name + " must be POSITION,AZIMUTH,ELEVATION" +
                    (slab ? "[,SLAB]" : "") +
                    ": a position 0 to 1 across the samples' box, the plane's normal in "
                    "degrees" +
                    (slab ? ", a slab's thickness 0 to 1" : "") + ", e.g. 0.5,0,90: '" + text +
                    "'");
  }
  return c;
}

}  // namespace

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
  if (!(shot.ball_opacity > 0 && shot.ball_opacity <= 1)) {
    throw io::Error("ball_opacity must be above 0 and at most 1: " +
                    std::to_string(shot.ball_opacity));
  }
  if (!shot.clip.empty() && !shot.section.empty())
    throw io::Error(
        "a picture is cut away at a plane (clip) or drawn in section (section), not both");
  if (!shot.clip.empty()) {
    request.clip = plane_from_text(shot.clip, "clip", /*slab=*/true);
    request.clipped = true;
  }
  if (!shot.section.empty()) {
    request.clip = plane_from_text(shot.section, "section", /*slab=*/false);
    request.sectioned = true;
  }
  request.step = shot.step;
  request.focus_sample = shot.focus_sample;
  request.focus_pole = shot.focus_pole;
  request.ball_every = shot.ball_every;
  request.polar_balls = shot.polar_balls;
  request.ball_limit = shot.ball_limit;
  scene::Colours colours = scene::Colours::paper;
  if (!scene::parse_colours(shot.palette, colours))
    throw io::Error("no palette '" + shot.palette + "' (palettes: paper, colour-blind)");
  request.colour_blind = colours == scene::Colours::colour_blind;
  request.ball_opacity = float(shot.ball_opacity);
  if (shot.neighbourhood && shot.focus_sample < 0)
    throw io::Error("the neighbourhood view needs a picked sample (focus_sample)");
  request.neighbourhood = shot.neighbourhood;
  request.layers = shot.layers;
  request.wireframe = shot.wireframe;
  request.smooth = shot.smooth;
  return request;
}

void check_shot_applies(const Shot& shot, const Any_reconstruction& reconstruction) {
  if (!shot.clip.empty() && reconstruction.index() == 0) {
    throw io::Error("a clip cuts a 3D scene open; this reconstruction is a 2D curve");
  }
  if (!shot.section.empty() && reconstruction.index() == 0) {
    throw io::Error("a section cuts a 3D scene by a plane; this reconstruction is a 2D curve");
  }
}

scene::Scene scene_of(const Shot& shot, const Any_reconstruction& reconstruction) {
  const scene::Request request = request_of(shot);
  check_shot_applies(shot, reconstruction);
  try {
    return std::visit([&](const auto& r) { return scene::build_scene(r, request); },
                      reconstruction);
  } catch (const std::invalid_argument& e) {
    throw io::Error(e.what());
  }
}

Picture draw_shot(render::Picture_renderer& renderer, const Shot& shot,
                  const Any_reconstruction& reconstruction, const nlohmann::json* inline_camera,
                  int legend_steps_before) {
  return draw_scene(renderer, shot, scene_of(shot, reconstruction), inline_camera,
                    legend_steps_before);
}

Picture draw_scene(render::Picture_renderer& renderer, const Shot& shot, scene::Scene scene,
                   const nlohmann::json* inline_camera, int legend_steps_before) {
  const auto [width, height] = parse_size(shot.size);
  Picture picture;
  picture.scene = std::move(scene);
  if (!shot.title.empty()) picture.scene.title = shot.title;
  float yaw = float(shot.yaw), pitch = float(shot.pitch);
  // A section is seen along its plane's normal, unless the shot turns the camera itself.
  if (picture.scene.seen_along && shot.yaw == Shot{}.yaw && shot.pitch == Shot{}.pitch)
    std::tie(yaw, pitch) = render::yaw_pitch_along(picture.scene.along);
  picture.camera = render::fit(picture.scene, float(width) / float(height), shot.zoom, yaw, pitch);
  if (inline_camera)
    picture.camera = camera_or_error(*inline_camera, picture.scene, "the shot's \"camera\"");
  if (!shot.camera_file.empty()) {
    picture.camera = camera_or_error(read_json(shot.camera_file), picture.scene,
                                     "the camera '" + shot.camera_file + "'");
  }
  render::Draw_options options;
  options.legend = options.title = !shot.no_legend;
  // A fitted camera that shows the whole shape steps back until the legend has a corner clear of
  // data, as the viewer's does; a camera given, or a zoom on a detail, stays where it was put.
  if (!inline_camera && shot.camera_file.empty() && shot.zoom >= 1 && options.legend) {
    for (int k = 0; k < legend_steps_before; ++k) picture.camera.zoom(render::legend_step_back);
    picture.camera = render::with_room_for_legend(
        render::Legend_layout(picture.scene), picture.camera, width, height, options,
        &picture.legend_steps, render::legend_steps_at_most - legend_steps_before);
    picture.legend_steps += legend_steps_before;
  }
  picture.image = renderer.render(picture.scene, picture.camera, width, height, options);
  return picture;
}

std::string output_format_problem(const Shot& shot) {
  if (shot.animate.empty()) {
    return io::extension_of(shot.output) == ".png"
               ? ""
               : "render writes PNG images: '" + shot.output + "' does not end in .png";
  }
  return render::animation_format_of(shot.output)
             ? ""
             : "an animation is written as animated WebP or GIF: '" + shot.output +
                   "' ends in neither .webp nor .gif";
}

namespace {

// A section across the middle facing a camera that looks from (yaw, pitch), as --section takes it.
std::string section_facing(double yaw, double pitch) {
  const scene::Clip plane =
      scene::facing({float(std::cos(pitch) * std::sin(yaw)), float(std::sin(pitch)),
                     float(std::cos(pitch) * std::cos(yaw))});
  std::ostringstream text;
  text.precision(9);
  text << plane.position << ',' << plane.azimuth << ',' << plane.elevation;
  return text.str();
}

}  // namespace

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
            // Edges of a 3D triangulation or diagram fill the picture with one colour: those
            // stages are drawn in section, at a plane across the middle facing the camera.
            const bool fills_space = stage == scene::Stage::delaunay ||
                                     stage == scene::Stage::voronoi ||
                                     stage == scene::Stage::crust_delaunay ||
                                     (stage == scene::Stage::sculpted_delaunay &&
                                      !joins_neighbours(r.options.method, r.options.kind, D));
            if (D == 3 && fills_space && shot.clip.empty() && shot.section.empty())
              frames.back().section = section_facing(shot.yaw, shot.pitch);
          }
          return;
        }
        // The replay of the stage asked for, when it is one (carving, candidates, front, alpha);
        // else the labelling's.
        scene::Stage stage = scene::Stage::propagation;
        if (scene::Stage asked; scene::parse_stage(shot.stage, asked) && scene::replays(asked))
          stage = asked;
        const bool labelling = stage == scene::Stage::propagation;
        if (!scene::has_stage(r.options.method, D, stage))
          throw io::Error(std::string("the method ") + to_string(r.options.method) +
                          (labelling ? " labels no poles: it has no replay (animate stages "
                                       "instead)"
                                     : " has no stage " + shot.stage + " to replay"));
        const long events = scene::replay_length(r, stage);
        if (events == 0)
          throw io::Error(labelling ? "no pole was labelled: there is no replay to animate"
                                    : "the stage " + shot.stage + " has no step to animate");
        const long count = std::clamp<long>(shot.frames, 2, events + 1);
        for (long k = 0; k < count; ++k) {
          frames.push_back(shot);
          frames.back().stage = scene::stage_id(stage);
          frames.back().step = (k * events + (count - 1) / 2) / (count - 1);
        }
      },
      reconstruction);
  return frames;
}

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
                        const Any_reconstruction& shown, const nlohmann::json* inline_camera,
                        std::optional<scene::Scene> built) {
  check_shot(shot);
  if (!shot.animate.empty()) {
    const int milliseconds = shot.frame_ms > 0          ? shot.frame_ms
                             : shot.animate == "replay" ? 80
                                                        : 1200;
    const auto [width, height] = parse_size(shot.size);
    // Each picture encoded as it is drawn: memory holds the compressed frames, not the pictures
    // (2,000 frames of 8192x8192 would be 500 GB).
#if defined(__GLIBC__)
    // And each picture given back once encoded: after the first large free glibc raises its
    // mmap threshold, and the next pictures, taken from the heap between smaller blocks, left it
    // fragmented (200 frames of 512x512 peaked at 780 MB, 40 at 240 MB). A fixed threshold keeps
    // large blocks mapped apart: 110 MB for either.
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    std::optional<render::Animation_writer> animation;
    try {
      animation.emplace(
          width, height, milliseconds,
          render::animation_format_of(shot.output).value_or(render::Animation_format::webp));
    } catch (const std::runtime_error& e) {
      throw io::Error(e.what());
    }
    scene::Scene last;
    // The replay follows the pole just labelled, as the viewer does (render::follow_point),
    // from the first picture's camera.
    std::optional<render::Camera> camera;  // the first picture's
    glm::vec3 lower{}, upper{};            // the samples' box
    bool framed_far = false;               // the camera frames a far pole with the shape
    int legend_steps = 0;                  // the legend's steps back so far
    for (const Shot& frame : animation_frames(shot, shown)) {
      nlohmann::json followed;
      if (camera && frame.stage == "propagation" && frame.step > 0) {
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
      // The legend's steps back only add up: the picture never jumps in and out between frames.
      Picture picture = draw_shot(renderer, frame, shown,
                                  followed.is_null() ? inline_camera : &followed, legend_steps);
      legend_steps = std::max(legend_steps, picture.legend_steps);
      if (!camera) {
        camera = picture.camera;
        lower = render::to_glm(picture.scene.lower);
        upper = render::to_glm(picture.scene.upper);
      }
      try {
        animation->add(picture.image);
      } catch (const std::runtime_error& e) {
        throw io::Error(e.what());
      }
      last = std::move(picture.scene);
    }
    if (!shot.save_camera.empty()) save_camera(*camera, shot.save_camera);
    try {
      animation->write(shot.output);
    } catch (const std::runtime_error& e) {
      throw io::Error(e.what());
    }
    return last;
  }
  Picture picture = built ? draw_scene(renderer, shot, std::move(*built), inline_camera)
                          : draw_shot(renderer, shot, shown, inline_camera);
  if (!shot.save_camera.empty()) save_camera(picture.camera, shot.save_camera);
  render::write_png(shot.output, picture.image);
  return std::move(picture.scene);
}

}  // namespace sculpt::frontend
