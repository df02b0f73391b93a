// SPDX-License-Identifier: GPL-3.0-or-later
// What the viewer writes and reads besides the input: pictures and animations of the view,
// drawn in-process as the figures are, the result as a mesh or curve, and the camera as JSON.
// In the browser each file written is handed to the user as a download (platform::deliver_file).
#include <imgui.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "frontend/shots.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"
#include "platform/platform.hpp"
#include "render/framebuffer.hpp"
#include "shapes/shapes.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

bool Viewer::export_animation(const std::string& path, int width, int height, int frames) {
  return export_shot(path, width, height, scene::replays(request_.stage) ? "replay" : "stages",
                     frames);
}

bool Viewer::export_picture(const std::string& path, int width, int height) {
  return export_shot(path, width, height, "", 0);
}

bool Viewer::export_shot(const std::string& path, int width, int height, const std::string& animate,
                         int frames) {
  if (!reconstruction_) {
    message_ = "nothing to save yet";
    return false;
  }
  if (!can_save_to(path)) return false;
  // The layers below are those of the stage on screen, even before a frame has drawn it.
  rebuild_scene();
  // The view on screen as a shot of the shown reconstruction, drawn by the figures' code into a
  // framebuffer of this window's context.
  frontend::Shot shot;
  shot.stage = scene::stage_id(request_.stage);
  shot.step = request_.step;
  shot.focus_sample = request_.focus_sample;
  shot.focus_pole = request_.focus_pole;
  shot.wireframe = request_.wireframe;
  shot.smooth = request_.smooth;
  shot.ball_every = request_.ball_every;
  shot.ball_limit = request_.ball_limit;
  shot.palette = colour_blind_ ? "colour-blind" : "paper";
  shot.ball_opacity = request_.ball_opacity;
  shot.polar_balls = request_.polar_balls;
  shot.neighbourhood = request_.neighbourhood && request_.focus_sample >= 0;
  shot.size = std::to_string(width) + "x" + std::to_string(height);
  shot.output = path;
  if (!animate.empty()) {
    shot.animate = animate;
    shot.frames = frames;
  }
  if ((request_.clipped || request_.sectioned) && reconstruction_->index() == 1) {  // 3D only
    const scene::Clip& c = request_.clip;
    std::ostringstream plane;
    plane << c.position << ',' << c.azimuth << ',' << c.elevation;
    if (request_.sectioned) {
      shot.section = plane.str();
    } else {
      plane << ',' << c.slab;
      shot.clip = plane.str();
    }
  }
  nlohmann::json camera;
  if (camera_is_panel_camera_ && !panel_on_screen().empty()) {
    // The panel's framing, refitted to the picture's size as the gallery does.
    const frontend::Shot& panel = tour_.image().shot;
    shot.zoom = panel.zoom;
    shot.yaw = panel.yaw;
    shot.pitch = panel.pitch;
  } else {
    camera = render::to_json(camera_);
  }
  // An animation shows other stages (or the replay's other steps): each its own layers.
  if (animate.empty()) {
    for (const auto& layer : renderer_->scene().layers) {
      if (layer.id == "true-curve") continue;  // the viewer's own overlay: not a stage's layer
      if (std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) == hidden_layers_.end())
        shot.layers.push_back(layer.id);
    }
  }
  try {
    if (!picture_renderer_)
      picture_renderer_ = std::make_unique<render::Context_picture_renderer>();
    frontend::write_shot(*picture_renderer_, shot, *reconstruction_,
                         camera.is_null() ? nullptr : &camera);
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
  platform::deliver_file(path);
  message_ = "saved " + path;
  return true;
}

bool Viewer::save_camera(const std::string& path) {
  try {
    io::check_destination(path);
    io::Atomic_file file(path, false);
    file.stream() << render::to_json(camera_).dump(2) << '\n';
    file.commit();
    platform::deliver_file(path);
    message_ = "camera saved to " + path;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

bool Viewer::load_camera(const std::string& path) {
  try {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const auto camera = render::camera_from_json(nlohmann::json::parse(in));
    if (camera.dimension != camera_.dimension)
      throw std::runtime_error("that camera is for another dimension");
    camera_ = camera;
    camera_fitted_ = true;
    message_ = "camera loaded from " + path;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

bool Viewer::save_result(const std::string& path) {
  if (!reconstruction_) {
    message_ = "nothing to save yet";
    return false;
  }
  try {
    io::check_destination(path);
    std::visit(
        [&](const auto& r) {
          constexpr int D = std::decay_t<decltype(r)>::dimension;
          // The samples as read (the first sites), or the vertices of a result that does not
          // interpolate: vertex i of the file is sample i, as the command line writes it.
          const auto& points = r.surface_points();
          const std::vector<Point<D>> vertices(
              points.begin(),
              points.begin() + (r.interpolates() ? r.sample_count() : points.size()));
          if constexpr (D == 3) {
            io::write_surface(path, vertices, r.surface, false);
          } else {
            io::write_curve(path, vertices, r.surface);
          }
        },
        *reconstruction_);
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
  platform::deliver_file(path);
  message_ = "saved " + path;
  return true;
}

bool Viewer::can_save_to(const std::string& path) {
  try {
    io::check_destination(path);  // not a folder, not a file this session opened
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

std::string Viewer::download_name(const std::string& extension) const {
  std::string input = shown_request_.example;
  if (input.empty()) {
    const std::string& path = shown_request_.path;
    input = path.substr(path.find_last_of('/') + 1);
    input = input.substr(0, input.find('.'));
  }
  if (shown_request_.edited_points) input = "edited";
  if (input.empty()) input = "sculpt";
  const std::string method =
      reconstruction_ ? to_string(options_of(*reconstruction_).method) : method_names()[method_];
  return input + "-" + method + "-" + scene::stage_id(request_.stage) + extension;
}

}  // namespace sculpt::viewer
