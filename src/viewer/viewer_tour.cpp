// SPDX-License-Identifier: GPL-3.0-or-later
// The tour of the paper's figures: a panel's reconstruction loaded (or taken from the recent
// ones), the stage walked, the labelling played and the camera flown to the panel's view; the
// Paper menu and the caption under the picture; exploring from a panel and back.
#include <imgui.h>

#include <algorithm>

#include "frontend/shots.hpp"
#include "readable_style.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

namespace {

constexpr double stage_dwell_seconds = 0.25;      // each stage walked through on the way to a panel
constexpr float camera_move_seconds = 0.7f;       // the camera's flight to a panel's
constexpr double propagation_play_seconds = 1.5;  // playing the labelling up to a panel's step

int rule_index(const std::string& name) {
  for (int i = 0; i < 3; ++i) {
    if (name == rule_names[i]) return i;
  }
  return 0;
}

// Eases in and out, so the camera does not jerk at either end of its flight.
float smoothstep(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

}  // namespace

bool Viewer::open_figure(const std::string& id, std::size_t panel) {
  const figures::Figure* figure = figures::find_figure(id);
  if (!figure || !tour_.open(*figure, panel)) {
    message_ = "no figure '" + id + "'" + (figure ? " panel " + std::to_string(panel + 1) : "") +
               " (figures are fig01 ... fig15)";
    return false;
  }
  show_tour_panel();
  return true;
}

bool Viewer::go_to_panel(const std::string& panel) {
  if (!tour_.go_to(panel)) {
    message_ = tour_.active() ? "no panel '" + panel + "' in " + tour_.figure().id
                              : "no figure is open (Paper menu)";
    return false;
  }
  show_tour_panel();
  return true;
}

bool Viewer::next_figure() {
  if (!tour_.next_figure()) return false;
  show_tour_panel();
  return true;
}

bool Viewer::previous_figure() {
  if (!tour_.previous_figure()) return false;
  show_tour_panel();
  return true;
}

void Viewer::return_to_panel() {
  if (!tour_.active()) return;
  tour_.return_to_panel();
  show_tour_panel();
}

void Viewer::close_tour() {
  if (tour_.active() && reconstruction_) message_ = "showing " + description_;
  tour_.close();
  panel_pending_ = panel_camera_pending_ = camera_is_panel_camera_ = false;
  stage_walk_.clear();
  play_until_ = -1;
  camera_move_.reset();
}

std::string Viewer::panel_on_screen() const {
  if (!tour_.active() || tour_.exploring() || moving_to_panel() || !reconstruction_) return "";
  return tour_.panel_id();
}

// The panel's reconstruction: the one shown, a recent one, or a new job.
void Viewer::show_tour_panel() {
  stop_editing();  // a figure shows its own input
  frontend::Shot shot;
  try {
    shot = cgal_meshes_.resolve(tour_.image().shot);
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    close_tour();
    return;
  }
  // The panel's options become the viewer's, so the options panel and a rerun show them.
  Method method = Options{}.method;
  parse_method(shot.method, method);
  set_method(method);
  kind_ = frontend::kind_of(shot);
  box_factor_ = static_cast<float>(shot.box_factor);
  alpha_ = static_cast<float>(shot.alpha);
  rule_ = rule_index(shot.rule);
  Job_request request;
  request.path = shot.input;
  request.example = shot.example;
  request.dimension = shot.dimension;
  const std::string& figure_input = tour_.image().shot.input;
  if (figure_input.rfind("cgal:", 0) == 0) request.shown_as = "CGAL's " + figure_input.substr(5);
  stage_walk_.clear();
  play_until_ = -1;
  const std::string key = request_key(with_options(request));
  walk_stages_ = animate_ && reconstruction_ && key == request_key(shown_request_);
  if (reconstruction_ && key == request_key(shown_request_)) {
    job_->abandon();  // a reconstruction for another panel is no longer wanted
    move_to_panel_view();
    return;
  }
  for (const Recent& recent : recent_) {
    if (recent.key != key) continue;
    job_->abandon();
    last_request_ = with_options(request);
    const auto reconstruction = recent.reconstruction;  // `recent` may not outlive show()
    show(reconstruction, recent.description);
    move_to_panel_view();
    return;
  }
  panel_pending_ = true;
  start_job(request);
}

// The stage, step, focus, layers and camera of the panel: at once, or walking through the
// stages between the one shown and the panel's while the camera flies to the panel's.
void Viewer::move_to_panel_view() {
  panel_pending_ = false;
  camera_move_.reset();
  const frontend::Shot& shot = tour_.image().shot;
  scene::Stage target = scene::Stage::surface;
  scene::parse_stage(shot.stage, target);
  const auto& stages = shown_stages();
  const auto at = [&](scene::Stage stage) {
    return std::find(stages.begin(), stages.end(), stage) - stages.begin();
  };
  stage_walk_.clear();
  if (walk_stages_) {
    const auto from = at(request_.stage), to = at(target);
    for (auto i = from; i != to;) {
      i += to > from ? 1 : -1;
      stage_walk_.push_back(stages[i]);
    }
    // On the way, each stage as it shows by default.
    request_ = default_view(request_.stage);
  }
  walk_clock_ = 0;
  if (stage_walk_.empty()) arrive_at_panel();
  hidden_layers_.clear();
  panel_camera_pending_ = true;
  scene_dirty_ = true;
  message_ = "showing " + tour_.panel_name() + ": " + tour_.image().what;
}

void Viewer::arrive_at_panel() {
  const frontend::Shot& shot = tour_.image().shot;
  // The panel's own view: its stage, step, focus, clip and layers, as the gallery draws it.
  const scene::Request request = frontend::request_of(shot);
  request_ = request;
  // A panel in the middle of the labelling: play it up to there.
  if (walk_stages_ && request.stage == scene::Stage::propagation && shot.step > 0) {
    play_until_ = std::min(shot.step, event_count());
    play_clock_ = 0;
    request_.step = 0;
  }
  scene_dirty_ = true;
}

void Viewer::advance_move_to_panel(double seconds) {
  if (!stage_walk_.empty()) {
    walk_clock_ += seconds;
    if (walk_clock_ >= stage_dwell_seconds) {
      walk_clock_ = 0;
      const scene::Stage next = stage_walk_.front();
      stage_walk_.pop_front();
      if (stage_walk_.empty()) {
        arrive_at_panel();
      } else {
        request_.stage = next;
        scene_dirty_ = true;
      }
    }
  } else if (play_until_ >= 0) {
    // At most a 30th of a second a frame: on a slow software renderer the play still shows
    // its frames instead of jumping to the end.
    play_clock_ += std::min(seconds, 1.0 / 30) *
                   std::max(20.0, double(play_until_) / propagation_play_seconds);
    request_.step = std::min(play_until_, long(play_clock_));
    if (request_.step >= play_until_) play_until_ = -1;
    scene_dirty_ = true;
  }
  if (camera_move_) {
    camera_move_->t = std::min(1.0f, camera_move_->t + float(seconds) / camera_move_seconds);
    camera_ =
        render::interpolate(camera_move_->from, camera_move_->to, smoothstep(camera_move_->t));
    if (camera_move_->t >= 1.0f) camera_move_.reset();
  }
}

void Viewer::explore() {
  if (!tour_.active() || tour_.exploring()) return;
  tour_.explore();
  stage_walk_.clear();
  play_until_ = -1;
  camera_move_.reset();
  // Every layer of every stage, and all polar balls, are the student's to show or hide again.
  request_.layers.clear();
  request_.ball_every = 1;
  scene_dirty_ = true;
}

// Every figure by number and caption, each with its panels.
void Viewer::draw_paper_menu() {
  if (!ImGui::BeginMenu("Paper")) return;
  if (ImGui::MenuItem("Start the tour at Fig. 1", "PgDn", false, !tour_.active()))
    open_figure("fig01");
  ImGui::Separator();
  for (const auto& figure : figures::paper_figures()) {
    std::string label = figure.caption;
    if (label.size() > 72) label = label.substr(0, label.rfind(' ', 69)) + " ...";
    const bool current = tour_.active() && &tour_.figure() == &figure;
    if (ImGui::BeginMenu(label.c_str())) {
      for (std::size_t i = 0; i < figure.images.size(); ++i) {
        const auto& image = figure.images[i];
        const std::string item = figures::panel_name(figure, i) + "  " + image.what;
        if (ImGui::MenuItem(item.c_str(), nullptr, current && tour_.panel() == i))
          open_figure(figure.id, i);
      }
      ImGui::EndMenu();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", ("Data: " + figure.data).c_str());
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Close the tour", "Esc", false, tour_.active())) close_tour();
  ImGui::EndMenu();
}

// Under the picture, as in the paper: the figure's caption, the paper's own sentence about it,
// and what this panel shows and why; with the buttons that walk the tour.
void Viewer::draw_caption(int width, int height) {
  if (!tour_.active()) {
    caption_height_ = 0;
    return;
  }
  const float caption_width = float(view_width(width));
  // The caption only grows within a figure, so the picture above it does not jump between panels.
  if (caption_figure_ != tour_.figure().id) {
    caption_figure_ = tour_.figure().id;
    caption_min_height_ = 0;
  }
  ImGui::SetNextWindowPos(ImVec2(panel_width(), float(height - reserved_height_)), ImGuiCond_Always,
                          ImVec2(0, 1));
  const float caption_max_height = 0.45f * float(height);
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(caption_width, std::min(caption_min_height_, caption_max_height)),
      ImVec2(caption_width, caption_max_height));
  ImGui::Begin("Paper", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings);
  // Wrapped short of the scroll bar, which a long caption at a large font brings.
  ImGui::PushTextWrapPos(caption_width - ImGui::GetStyle().WindowPadding.x -
                         ImGui::GetStyle().ScrollbarSize);
  const figures::Figure& figure = tour_.figure();
  const figures::Figure_image& image = tour_.image();

  const std::size_t count = figure.images.size();
  ImGui::TextColored(imgui_colour(panel_colours::current_line), "%s", tour_.panel_name().c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("panel %zu of %zu", tour_.panel() + 1, count);
  ImGui::SameLine();
  if (ImGui::SmallButton("< previous")) go_to_panel("previous");
  ImGui::SameLine();
  if (ImGui::SmallButton("next >")) go_to_panel("next");
  ImGui::SameLine();
  if (tour_.exploring()) {
    if (ImGui::SmallButton(("back to " + tour_.panel_name() + " (T)").c_str())) return_to_panel();
  } else if (ImGui::SmallButton("explore")) {
    explore();
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("close")) close_tour();

  // Where our input contradicts the caption, the class reads it first, never below the
  // strip's fold and never on hover only.
  if (!figure.contradiction.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, imgui_colour(panel_colours::contradiction));
    ImGui::TextWrapped("Differs from the paper: %s", figure.contradiction.c_str());
    ImGui::PopStyleColor();
  }
  // What is on screen before the paper's caption and sentence, which a long figure pushes
  // below the strip's fold.
  if (tour_.exploring()) {
    ImGui::TextWrapped(
        "Exploring from %s: every tool of the viewer works on this "
        "reconstruction. T (or the button above) returns to the panel.",
        tour_.panel_name().c_str());
  } else {
    ImGui::TextWrapped("%s%s. %s", image.suffix.empty() ? "" : ("(" + image.suffix + ") ").c_str(),
                       image.what.c_str(), image.why.c_str());
  }
  ImGui::TextUnformatted(figure.caption.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, imgui_colour(panel_colours::caption));
  ImGui::TextWrapped("Paper: \"%s\"", figure.sentence.c_str());
  ImGui::PopStyleColor();
  if (!figure.differences.empty()) {
    ImGui::TextDisabled(figure.contradiction.empty() ? "Differs from the paper (hover)"
                                                     : "Why, and the data (hover)");
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(420);
      ImGui::TextUnformatted(("Data: " + figure.data + ". " + figure.differences).c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
  ImGui::PopTextWrapPos();
  caption_height_ = int(ImGui::GetWindowHeight());
  caption_min_height_ = std::max(caption_min_height_, ImGui::GetWindowHeight());
  ImGui::End();
}

}  // namespace sculpt::viewer
