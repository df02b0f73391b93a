// What the viewer writes and reads besides the input: pictures and animations of the view,
// drawn in-process as the figures are, and the camera as JSON; the File, Examples and View menus.
#include <imgui.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "frontend/shots.hpp"
#include "io/atomic_file.hpp"
#include "render/framebuffer.hpp"
#include "shapes/shapes.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

void Viewer::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    ImGui::InputText("##path", path_field_, sizeof path_field_);
    ImGui::SameLine();
    if (ImGui::Button("Open")) open_file(path_field_);
    ImGui::TextDisabled("or drop a point file on the window");
    ImGui::Separator();
    ImGui::InputText("camera file", camera_field_, sizeof camera_field_);
    if (ImGui::MenuItem("Save camera")) save_camera(camera_field_);
    if (ImGui::MenuItem("Load camera")) load_camera(camera_field_);
    ImGui::Separator();
    ImGui::InputText("picture", picture_field_, sizeof picture_field_);
    ImGui::InputInt2("size", picture_size_);
    if (ImGui::MenuItem("Save picture", "P"))
      export_picture(picture_field_, picture_size_[0], picture_size_[1]);
    ImGui::InputText("animation", animation_field_, sizeof animation_field_);
    if (ImGui::MenuItem("Save animation (WebP)")) {
      // The replay at the propagation stage, else a sweep of the stages.
      export_animation(animation_field_, picture_size_[0], picture_size_[1]);
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) quit_ = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Examples")) {
    for (const auto& e : shapes::examples()) {
      if (ImGui::MenuItem((e.name + " (" + std::to_string(e.dimension) + "D)").c_str(), nullptr,
                          false, !busy())) {
        open_example(e.name);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.description.c_str());
    }
    ImGui::EndMenu();
  }
  draw_paper_menu();
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Fit / reset camera", "R")) reset_camera(), scene_dirty_ = true;
    if (ImGui::MenuItem("Controls", "H", show_help_)) show_help_ = !show_help_;
    // Projector mode: text large enough for the back of a room.
    ImGui::SliderFloat("text size", &ImGui::GetIO().FontGlobalScale, 0.5f, 3.0f, "%.1fx");
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

bool Viewer::export_animation(const std::string& path, int width, int height, int frames) {
  return export_shot(path, width, height,
                     request_.stage == scene::Stage::propagation ? "replay" : "stages", frames);
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
  shot.polar_balls = request_.polar_balls;
  shot.neighbourhood = request_.neighbourhood && request_.focus_sample >= 0;
  shot.size = std::to_string(width) + "x" + std::to_string(height);
  shot.output = path;
  if (!animate.empty()) {
    shot.animate = animate;
    shot.frames = frames;
  }
  if (request_.clipped) {
    const scene::Clip& c = request_.clip;
    std::ostringstream clip;
    clip << c.position << ',' << c.azimuth << ',' << c.elevation << ',' << c.slab;
    shot.clip = clip.str();
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
  message_ = "saved " + path;
  return true;
}

bool Viewer::save_camera(const std::string& path) {
  try {
    io::Atomic_file file(path, false);
    file.stream() << render::to_json(camera_).dump(2) << '\n';
    file.commit();
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

}  // namespace sculpt::viewer
