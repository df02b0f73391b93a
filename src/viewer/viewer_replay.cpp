// SPDX-License-Identifier: GPL-3.0-or-later
// The replay of the pole labelling, event by event: the step shown, play and pause, its
// controls. It follows the action: the pole just labelled is kept in view (render::follow_point:
// near the shape the camera pans, keeping its zoom; a seed far out is framed with the shape),
// and what lies outside the view (the pole just labelled when following is off, the outer seeds
// far out by the box corners) gets an arrow at the edge pointing to it.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <string>

#include "scene/carving_replay.hpp"
#include "scene/growth_stages.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

void Viewer::set_step(long events) {
  explore();
  request_.step = events < 0 ? -1 : std::min(events, event_count());
  scene_dirty_ = true;
  follow_latest_event();
}

long Viewer::event_count() const {
  if (!reconstruction_) return 0;
  if (counted_reconstruction_.lock() != reconstruction_ || counted_stage_ != request_.stage) {
    const scene::Stage stage =
        scene::replays(request_.stage) ? request_.stage : scene::Stage::propagation;
    counted_events_ = std::visit(
        [&](const auto& r) {
          return scene::has_stage(r.options.method, r.dimension, stage)
                     ? scene::replay_length(r, stage)
                     : long(r.propagation.events.size());
        },
        *reconstruction_);
    counted_reconstruction_ = reconstruction_;
    counted_stage_ = request_.stage;
  }
  return counted_events_;
}

long Viewer::shown_step() const {
  if (request_.step >= 0) return std::min(request_.step, event_count());
  // The alpha shape opens at the method's own alpha, not at the hull every cell makes.
  if (reconstruction_ && request_.stage == scene::Stage::alpha) {
    if (const auto* r = std::get_if<Reconstruction<3>>(reconstruction_.get()))
      return long(r->alpha.chosen);
  }
  return event_count();
}

const Labelling_event* Viewer::latest_event() const {
  if (!reconstruction_ || request_.stage != scene::Stage::propagation) return nullptr;
  return std::visit(
      [&](const auto& r) -> const Labelling_event* {
        const long shown = request_.step < 0 ? long(r.propagation.events.size()) : request_.step;
        return shown > 0 ? &r.propagation.events[shown - 1] : nullptr;
      },
      *reconstruction_);
}

bool Viewer::has_replay() const {
  if (!reconstruction_) return false;
  const Options& options = options_of(*reconstruction_);
  for (scene::Stage stage : scene::stages_of(options.method, shown_dimension())) {
    if (scene::replays(stage)) return true;
  }
  return false;
}

bool Viewer::start_replay(scene::Stage stage, float pace) {
  if (!scene::replays(stage)) {
    message_ = std::string("the stage ") + scene::stage_id(stage) +
               " does not replay; the replays are propagation (the labelling), carving, "
               "candidates (the pruning), front (the Advancing Front) and alpha (alpha shapes)";
    return false;
  }
  if (!set_stage(stage)) return false;
  set_step(0);
  // A replay of thousands of steps plays in about ten seconds; the labelling at its pace.
  if (pace > 0)
    events_per_second_ = std::clamp(pace, 1.0f, 2000.0f);
  else if (stage != scene::Stage::propagation)
    events_per_second_ = std::clamp(float(event_count()) / 10.0f, 5.0f, 2000.0f);
  playing_ = true;
  playback_clock_ = 0;
  return true;
}

void Viewer::advance_playback(double seconds) {
  if (!playing_ || !scene::replays(request_.stage)) return;
  playback_clock_ += seconds * events_per_second_;
  const long steps = long(playback_clock_);
  if (steps == 0) return;
  playback_clock_ -= double(steps);
  const long current = shown_step();
  if (current >= event_count()) {
    playing_ = false;
    return;
  }
  set_step(current + steps);
}

void Viewer::draw_propagation_controls() {
  const long total = event_count();
  int shown = int(shown_step());
  if (ImGui::Button(playing_ ? "Pause" : "Play")) {
    if (!playing_ && shown >= total) set_step(0);
    playing_ = !playing_;
  }
  ImGui::SameLine();
  if (ImGui::Button("<")) set_step(std::max(0, shown - 1));
  ImGui::SameLine();
  if (ImGui::Button(">")) set_step(shown + 1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  ImGui::SliderFloat("events/s", &events_per_second_, 1.0f, 2000.0f, "%.0f",
                     ImGuiSliderFlags_Logarithmic);
  const bool carving = request_.stage == scene::Stage::carving;
  ImGui::SetNextItemWidth(std::max(120.0f, ImGui::GetContentRegionAvail().x - 60));
  const bool labelling = request_.stage == scene::Stage::propagation;
  if (ImGui::SliderInt(labelling ? "event" : "step", &shown, 0, int(total))) set_step(shown);
  if (request_.stage != scene::Stage::propagation) {
    const std::string line = std::visit(
        [&](const auto& r) -> std::string {
          if constexpr (std::decay_t<decltype(r)>::dimension == 3) {
            if (request_.stage == scene::Stage::front || request_.stage == scene::Stage::alpha)
              return scene::describe_growth(r, request_.stage, shown);
          }
          if (!carving)
            return shown == 0 ? "before any candidate is pruned"
                              : "step " + std::to_string(shown) + " of " + std::to_string(total) +
                                    ": a candidate pruned";
          if (shown == 0) return "before any cell leaves";
          return scene::describe_step(*scene::shared_carving_replay(r), std::size_t(shown - 1),
                                      r.dimension, r.carving);
        },
        *reconstruction_);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(line.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  if (ImGui::Checkbox("follow the action", &follow_) && follow_) follow_latest_event();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Pan to the pole just labelled whenever it leaves the view");
  if (const Labelling_event* e = latest_event()) {
    ImGui::Text("pole %d <- %s (%s", e->pole, to_string(e->label),
                reason_name(e->reason, dimension_of(*reconstruction_)));
    ImGui::SameLine(0, 0);
    if (e->source >= 0) {
      ImGui::Text(" of pole %d)", e->source);
    } else {
      ImGui::TextUnformatted(")");
    }
  }
}

std::vector<Viewer::Point_of_interest> Viewer::points_of_interest() const {
  std::vector<Point_of_interest> points;
  if (!reconstruction_) return points;
  std::visit(
      [&](const auto& r) {
        if (request_.stage == scene::Stage::propagation) {
          if (const Labelling_event* e = latest_event())
            points.push_back({render::to_glm(r.poles.poles[e->pole].center),
                              "pole " + std::to_string(e->pole) + " just labelled"});
          // Following a seed far out leaves the shape behind: an arrow leads back to it.
          const scene::Scene& scene = renderer_->scene();
          points.push_back(
              {(render::to_glm(scene.lower) + render::to_glm(scene.upper)) * 0.5f, "the samples"});
        } else if (request_.stage == scene::Stage::seeds) {
          for (int seed : r.seeds.outer_seeds)
            points.push_back({render::to_glm(r.poles.poles[seed].center), "outer seeds"});
        }
      },
      *reconstruction_);
  return points;
}

void Viewer::follow_latest_event() {
  if (!follow_ || request_.stage != scene::Stage::propagation || frame_height_ <= 0) return;
  const auto points = points_of_interest();
  if (points.empty()) return;
  const float aspect = float(view_width(frame_width_)) / float(view_height(frame_height_));
  // From where the camera is going, if it is already moving; a point behind a 3D camera is
  // left to the arrow.
  render::Camera camera = camera_move_ ? camera_move_->to : camera_;
  const auto& scene = renderer_->scene();
  const bool framed_far_before = far_framing_ && render::same_view(camera, *far_framing_);
  const render::Follow moved =
      render::follow_point(camera, points.front().at, render::to_glm(scene.lower),
                           render::to_glm(scene.upper), aspect, framed_far_before);
  if (moved == render::Follow::stayed) return;
  if (moved == render::Follow::framed_far) {
    far_framing_ = camera;
  } else {
    far_framing_.reset();
  }
  camera_move_ = Camera_move{camera_, camera, 0.0f};
  camera_is_panel_camera_ = false;
}

// For each point of interest outside the view, a small arrow at the view's edge pointing to it,
// labelled once per direction.
// Off-screen points are gathered by direction: one arrow for each sixteenth of the turn that
// holds any, with how many it stands for (the thousands of outer seeds of a 3D example would
// otherwise merge into a solid frame around the picture).
void Viewer::draw_off_screen_markers(int width, int height) {
  const auto points = points_of_interest();
  if (points.empty()) return;
  const float left = panel_width(), top = float(menu_bar_height_);
  const float view_w = float(view_width(width)), view_h = float(view_height(height));
  const glm::mat4 view_projection = camera_.projection(view_w / view_h) * camera_.view();
  constexpr int sectors = 16;
  struct Gathered {
    glm::vec2 direction{0.0f};  // the sum of the points' directions from the centre (NDC)
    int count = 0;
    std::string label;  // the first point's
  };
  std::array<Gathered, sectors> gathered;
  for (const auto& point : points) {
    glm::vec4 clip = view_projection * glm::vec4(point.at, 1.0f);
    // Behind the camera the direction flips: mirror it so the arrow points the right way.
    if (clip.w <= 0) clip = -clip;
    const glm::vec2 ndc = glm::vec2(clip) / std::max(clip.w, 1e-6f);
    if (std::abs(ndc.x) <= 1 && std::abs(ndc.y) <= 1) continue;
    const float turn = std::atan2(ndc.y, ndc.x) / (2 * glm::pi<float>()) + 0.5f;  // 0..1
    Gathered& sector = gathered[std::min(sectors - 1, int(turn * sectors))];
    sector.direction += glm::normalize(ndc);
    if (sector.count++ == 0) sector.label = point.label;
  }
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImU32 colour = IM_COL32(200, 40, 160, 255);
  const float scale = std::max(1.0f, picture_scale_);  // a projector's arrows are bigger
  int labelled_sides = 0;  // one label per side of the view (bit per side)
  for (const Gathered& sector : gathered) {
    if (sector.count == 0 || glm::length(sector.direction) < 1e-6f) continue;
    const glm::vec2 ndc = glm::normalize(sector.direction);
    // Where the line from the centre leaves the view, a little inside it.
    const float reach = std::max(std::abs(ndc.x), std::abs(ndc.y));
    const glm::vec2 edge = ndc / reach * 0.93f;
    const ImVec2 tip(left + (edge.x + 1) * 0.5f * view_w,
                     std::max(top + 10 * scale, (1 - edge.y) * 0.5f * view_h));
    const glm::vec2 direction = glm::normalize(glm::vec2(ndc.x, -ndc.y));
    const glm::vec2 across(-direction.y, direction.x);
    const auto corner = [&](float back, float side) {
      return ImVec2(tip.x - direction.x * back * scale + across.x * side * scale,
                    tip.y - direction.y * back * scale + across.y * side * scale);
    };
    draw->AddTriangleFilled(tip, corner(16, 7), corner(16, -7), colour);
    const int side = std::abs(ndc.x) >= std::abs(ndc.y) ? (ndc.x > 0 ? 1 : 2) : (ndc.y > 0 ? 4 : 8);
    std::string text = sector.count > 1 ? std::to_string(sector.count) : "";
    if (!(labelled_sides & side)) {
      labelled_sides |= side;
      text = sector.label + (text.empty() ? "" : " (" + text + ")");
    }
    if (text.empty()) continue;
    // Behind the arrow, clear of it whichever way it points, and inside the view.
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    ImVec2 at = corner(
        20 + 0.5f * (std::abs(direction.x) * size.x + std::abs(direction.y) * size.y) / scale, 0);
    // (max of min, not clamp: in a narrow view the upper bound may fall below the lower.)
    at.x = std::max(left + 4, std::min(at.x - size.x / 2, left + view_w - size.x - 4));
    at.y = std::max(top + 4, std::min(at.y - size.y / 2, view_h - size.y - 4));
    draw->AddText(at, colour, text.c_str());
  }
}

}  // namespace sculpt::viewer
