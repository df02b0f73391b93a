// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's live 2D editing: the shown samples become editable, each edit (the mouse, the
// Edit samples panel or a script) reconstructs them with the chosen method, and the curve a
// built-in example was sampled from is drawn beside the result.
#include <imgui.h>

#include <cmath>
#include <glm/glm.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include "frontend/statistics_json.hpp"
#include "io/destinations.hpp"
#include "io/point_reader.hpp"
#include "picking.hpp"
#include "platform/platform.hpp"
#include "scene/palette.hpp"
#include "shapes/shapes.hpp"
#include "viewer.hpp"

namespace sculpt::viewer {

bool Viewer::begin_editing() {
  if (editor_.active()) return true;
  if (!reconstruction_ || reconstruction_->index() != 0) {
    message_ = "samples can be edited in 2D only";
    return false;
  }
  // While another input is being read and reconstructed, the samples on screen are not the
  // ones the next picture will show.
  if (job_->running() || job_->outcome_waiting()) {
    message_ = "wait for the reconstruction to finish before editing";
    return false;
  }
  const auto& r = std::get<Reconstruction<2>>(*reconstruction_);
  std::vector<Point<2>> samples(r.sites.begin(), r.sites.begin() + r.sample_count());
  const std::string origin = shown_request_.edited_points ? shown_request_.edited_from
                             : shown_request_.example.empty()
                                 ? "edited from " + shown_request_.path
                                 : "edited from example " + shown_request_.example;
  editor_.start(std::move(samples), origin);
  show_true_curve_ = !truth_example_.empty();
  return true;
}

void Viewer::stop_editing() {
  editor_.stop();
  edits_pending_ = false;
  dragged_sample_ = -1;
  stroke_.clear();
  stroke_on_screen_.clear();
}

bool Viewer::edited(bool succeeded) {
  if (!succeeded) {
    message_ = editor_.why();
    return false;
  }
  explore();
  edits_pending_ = true;
  // A picked index is the reconstruction's on screen, no longer the edited points'.
  request_.focus_sample = request_.focus_pole = -1;
  return true;
}

void Viewer::reconstruct_edits() {
  edits_pending_ = false;
  Job_request request;
  request.edited_points = std::make_shared<const std::vector<Point<2>>>(editor_.points());
  request.edited_from = editor_.origin();
  request.edits = editor_.edits();
  request.dimension = 2;
  start_job(std::move(request));
}

bool Viewer::add_point(const Point<2>& p) {
  return begin_editing() && edited(editor_.add(p));
}

bool Viewer::move_point(int sample, const Point<2>& to) {
  return begin_editing() && edited(editor_.move(sample, to));
}

bool Viewer::delete_point(int sample) {
  if (!begin_editing()) return false;
  if (request_.focus_sample == sample) request_.focus_sample = -1;
  return edited(editor_.remove(sample));
}

bool Viewer::add_stroke(const std::vector<Point<2>>& stroke, double spacing) {
  if (!begin_editing()) return false;
  const auto& scene = renderer_->scene();
  const double diagonal =
      std::hypot(scene.upper[0] - scene.lower[0], scene.upper[1] - scene.lower[1]);
  const double step = spacing * (diagonal > 0 ? diagonal : 1.0);
  return edited(editor_.add_all(shapes::resample_polyline(stroke, step)));
}

bool Viewer::undo_edit() {
  if (!editor_.active()) {
    message_ = "nothing to undo";
    return false;
  }
  return edited(editor_.undo());
}

bool Viewer::save_points(const std::string& path) {
  if (!reconstruction_ || reconstruction_->index() != 0) {
    message_ = "only 2D samples are saved as points";
    return false;
  }
  if (io::extension_of(path) != ".xy") {
    message_ = "error: the samples are saved as .xy text (x y per line): '" + path + "'";
    return false;
  }
  try {
    io::check_destination(path);
    const auto& r = std::get<Reconstruction<2>>(*reconstruction_);
    const std::vector<Point<2>> samples =
        editor_.active()
            ? editor_.points()
            : std::vector<Point<2>>(r.sites.begin(), r.sites.begin() + r.sample_count());
    viewer::save_points(path, samples);
    platform::deliver_file(path);
    message_ = "saved " + std::to_string(samples.size()) + " samples to " + path;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

bool Viewer::set_layer_visible(const std::string& id, bool visible) {
  const auto ids = scene::layer_ids(renderer_->scene());
  if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
    std::string names;
    for (const auto& name : ids) names += (names.empty() ? "" : ", ") + name;
    message_ = "no layer '" + id + "' at this stage (its layers: " + names + ")";
    return false;
  }
  explore();
  hidden_layers_.erase(std::remove(hidden_layers_.begin(), hidden_layers_.end(), id),
                       hidden_layers_.end());
  if (!visible) hidden_layers_.push_back(id);
  return true;
}

std::string Viewer::statistics_line() const {
  if (!reconstruction_) return "";
  return std::visit([](const auto& r) { return frontend::statistics_json(r.stats).dump(); },
                    *reconstruction_);
}

// The inverse of the 2D camera: where in the plane a pixel of the view lies.
Point<2> Viewer::world_at(glm::vec2 mouse, int width, int height) const {
  const glm::mat4 inverse =
      glm::inverse(camera_.projection(float(width) / height) * camera_.view());
  const glm::vec4 ndc(2 * mouse.x / width - 1, 1 - 2 * mouse.y / height, 0, 1);
  const glm::vec4 world = inverse * ndc;
  return {world.x / world.w, world.y / world.w};
}

// Editing with the mouse: a click in empty space adds a sample, a drag from a sample moves it,
// a right click on one deletes it, and Shift+drag draws a stroke that becomes samples. A click
// on a sample still selects it. Returns false to leave the mouse to the camera.
bool Viewer::handle_editing_input(int width, int height) {
  if (reconstruction_->index() != 0) return false;
  const ImGuiIO& io = ImGui::GetIO();
  const int view_w = view_width(width);
  const int view_h = view_height(height);
  const glm::vec2 mouse(io.MousePos.x - panel_width(), io.MousePos.y - float(menu_bar_height_));
  const glm::mat4 view_projection = camera_.projection(float(view_w) / view_h) * camera_.view();
  const glm::vec2 viewport(view_w, view_h);
  const Point<2> at = world_at(mouse, view_w, view_h);
  // The samples as edited, or those on screen before the first edit.
  const auto& r = std::get<Reconstruction<2>>(*reconstruction_);
  const std::vector<Point<2>>& samples = editor_.active() ? editor_.points() : r.sites;
  const std::size_t sample_count = editor_.active() ? samples.size() : r.sample_count();
  const auto sample_under_mouse = [&] {
    return pick_nearest<2>(samples, sample_count, view_projection, mouse, viewport);
  };

  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    dragged_sample_ = -1;
    stroke_.clear();
    stroke_on_screen_.clear();
    if (io.KeyShift) {
      stroke_.push_back(at);
      stroke_on_screen_.push_back({io.MousePos.x, io.MousePos.y});
    } else if ((dragged_sample_ = sample_under_mouse()) >= 0) {
      if (begin_editing()) {
        editor_.begin_drag();
      } else {
        dragged_sample_ = -1;
      }
    }
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    if (!stroke_.empty()) {
      const auto& last = stroke_on_screen_.back();
      if (std::hypot(io.MousePos.x - last[0], io.MousePos.y - last[1]) >= 3.0f) {
        stroke_.push_back(at);
        stroke_on_screen_.push_back({io.MousePos.x, io.MousePos.y});
      }
      std::vector<ImVec2> line;
      for (const auto& p : stroke_on_screen_) line.emplace_back(p[0], p[1]);
      ImGui::GetForegroundDrawList()->AddPolyline(line.data(), int(line.size()),
                                                  IM_COL32(200, 60, 160, 255), 0, 2.0f);
      return true;
    }
    if (dragged_sample_ >= 0 && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
      if (editor_.active() && editor_.drag(dragged_sample_, at)) edited(true);
      return true;
    }
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    const bool clicked = drag.x * drag.x + drag.y * drag.y < 9.0f;
    const int dragged = dragged_sample_;
    dragged_sample_ = -1;
    if (!stroke_.empty()) {
      const auto stroke = std::move(stroke_);
      stroke_.clear();
      stroke_on_screen_.clear();
      if (stroke.size() > 1) {
        add_stroke(stroke, stroke_spacing_);
      } else {
        add_point(stroke.front());
      }
      return true;
    }
    if (clicked && dragged >= 0) {
      // A click on a sample selects it, once the picture shows the points as edited.
      if (!edits_pending_ && !job_->running()) pick_sample(dragged);
      return true;
    }
    if (clicked) {
      add_point(at);
      return true;
    }
    if (dragged >= 0) return true;
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Right)) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0.0f);
    const int under = sample_under_mouse();
    if (drag.x * drag.x + drag.y * drag.y < 9.0f && under >= 0) {
      delete_point(under);
      return true;
    }
  }
  return dragged_sample_ >= 0;
}

// The curve the example was sampled from, thin and light under everything: what the samples
// are meant to give back, so an undersampled valley shows where the result leaves it.
void Viewer::add_true_curve(scene::Scene& scene) const {
  if (!show_true_curve_ || truth_example_.empty() || scene.dimension != 2) return;
  static std::map<std::string, shapes::Sampled_curve> curves;  // drawn once per example
  auto found = curves.find(truth_example_);
  if (found == curves.end())
    found = curves.emplace(truth_example_, shapes::example_curve_2(truth_example_)).first;
  scene::Layer layer;
  layer.id = "true-curve";
  layer.label = "the curve sampled (ground truth)";
  layer.primitive = scene::Primitive::lines;
  layer.color = scene::palette::true_curve;
  layer.size = 6.0f;
  for (const auto& edge : found->second.edges) {
    for (int end : edge) {
      const Point<2>& p = found->second.samples[end];
      layer.positions.push_back({float(p[0]), float(p[1]), 0.0f});
    }
  }
  scene.layers.insert(scene.layers.begin(), std::move(layer));  // drawn first: underneath
}

void Viewer::draw_editing_controls() {
  if (!ImGui::CollapsingHeader("Edit samples (2D)")) return;
  if (ImGui::Checkbox("edit with the mouse (E)", &editing_) && editing_ && !begin_editing())
    editing_ = false;
  ImGui::TextDisabled("click adds, drag moves, right click deletes,\nShift+drag draws a stroke");
  ImGui::SliderFloat("stroke spacing", &stroke_spacing_, 0.005f, 0.2f, "%.3f",
                     ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "How far apart a drawn stroke's samples are, as a share of the samples' box diagonal: "
        "wide spacing undersamples");
  if (!truth_example_.empty() && ImGui::Checkbox("show the true curve", &show_true_curve_))
    scene_dirty_ = true;
  if (editor_.active()) {
    ImGui::Text("%zu samples, %d edits", editor_.points().size(), editor_.edits());
    if (ImGui::Button("Undo (U)")) undo_edit();
    ImGui::SameLine();
  }
  if (ImGui::Button("Save points")) save_points(points_field_);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##points", points_field_, sizeof points_field_);
}

}  // namespace sculpt::viewer
