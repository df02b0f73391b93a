// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's state and its frame: what is reconstructed (each input a background job, the last
// few kept), what is shown of it (stage, selection, camera), and one frame drawn. The panels,
// the input, the replay, the tour and the files each have a file of their own (viewer_*.cpp).
#include "viewer.hpp"

// clang-format off
// Our GL header first: it must be the first to include the platform's GL header.
#include "render/gl.hpp"
// clang-format on
#include <imgui.h>

#include "io/destinations.hpp"
#include "render/legend_layout.hpp"
#include "scene/clipping.hpp"
#include "shapes/shapes.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

namespace {

constexpr std::size_t recent_reconstructions = 4;

}  // namespace

float Viewer::panel_width() const {
  return presenting_ ? 0.0f : 360.0f * std::max(1.0f, ImGui::GetIO().FontGlobalScale);
}

int Viewer::view_width(int window_width) const {
  return std::max(1, window_width - int(panel_width()));
}

Viewer::Viewer() : renderer_(std::make_unique<render::Renderer>()) {}

void Viewer::open_example(const std::string& name, Surface_kind kind) {
  close_tour();
  stop_editing();
  Job_request request;
  request.example = name;
  if (const auto* example = shapes::find_example(name)) {
    kind_ =
        frontend::input_kind(example, kind == Surface_kind::bordered, kind == Surface_kind::closed);
  }
  start_job(request);
}

void Viewer::open_file(const std::string& path) {
  close_tour();
  stop_editing();
  Job_request request;
  request.path = path;
  io::remember_input(path);  // no save of this session may replace it
  kind_ = file_kind_;        // a file: as asked on the command line, else chosen from its samples
  std::snprintf(path_field_, sizeof path_field_, "%s", path.c_str());
  start_job(request);
}

void Viewer::rerun() {
  explore();
  if (editor_.active()) {
    reconstruct_edits();
  } else {
    start_job(last_request_);
  }
}

bool Viewer::switch_method(const std::string& name) {
  Method method;
  if (!parse_method(name, method)) {
    message_ = "no method '" + name + "'";
    return false;
  }
  if (last_request_.path.empty() && last_request_.example.empty() && !editor_.active()) {
    message_ = "nothing loaded to reconstruct";
    return false;
  }
  set_method(method);
  rerun();
  return true;
}

bool Viewer::switch_cleaning(const std::string& name) {
  const auto known = std::find_if(std::begin(cleaning_names), std::end(cleaning_names),
                                  [&](const char* n) { return name == n; });
  if (known == std::end(cleaning_names)) {
    message_ = "no cleaning '" + name + "' (" + cleaning_choices() + ")";
    return false;
  }
  if (last_request_.path.empty() && last_request_.example.empty() && !editor_.active()) {
    message_ = "nothing loaded to reconstruct";
    return false;
  }
  cleaning_ = int(known - std::begin(cleaning_names));
  rerun();
  return true;
}

Job_request Viewer::with_options(Job_request request) const {
  request.options.method = method_at(method_);
  request.options.kind = kind_;
  request.options.box_factor = box_factor_;
  request.options.alpha = alpha_;
  request.merge_duplicates = merge_duplicates_;
  request.options.rule = rule_ == 1   ? Surface_rule::skin
                         : rule_ == 2 ? Surface_rule::extraction
                                      : Surface_rule::automatic;
  parse_cleaning(cleaning_names[cleaning_], request.options.cleaning);
  return request;
}

void Viewer::start_job(Job_request request) {
  request = with_options(std::move(request));
  last_request_ = request;
  last_job_failed_ = false;  // a new attempt: its outcome will say
  message_ = "reconstructing " + (request.edited_points     ? "the edited samples"
                                  : request.example.empty() ? request.path
                                                            : "example " + request.example);
  job_->start(std::move(request));
}

void Viewer::take_finished_job() {
  auto outcome = job_->take_outcome();
  if (!outcome) return;
  if (!outcome->error.empty()) {
    message_ = outcome->error == "cancelled" ? "cancelled" : "error: " + outcome->error;
    last_job_failed_ = outcome->error != "cancelled";
    // A panel whose reconstruction did not come cannot be shown: the tour ends there.
    if (panel_pending_) close_tour();
    return;
  }
  auto reconstruction =
      std::make_shared<const Any_reconstruction>(std::move(*outcome->reconstruction));
  recent_.push_front({request_key(last_request_), reconstruction, outcome->description});
  if (recent_.size() > recent_reconstructions) recent_.pop_back();
  show(std::move(reconstruction), outcome->description);
  if (panel_pending_) move_to_panel_view();
}

void Viewer::show(std::shared_ptr<const Any_reconstruction> reconstruction,
                  std::string description) {
  const bool same_dimension =
      reconstruction_ && reconstruction_->index() == reconstruction->index();
  // Another method or an edit of the same points keeps the camera (a class compares them in
  // one view); another model is framed afresh.
  const bool same_input = reconstruction_ && (last_request_.edited_points ||
                                              (shown_request_.path == last_request_.path &&
                                               shown_request_.example == last_request_.example));
  // Other points, or the same edited: the methods compared were of the points before.
  if (!same_input || last_request_.edited_points) stop_compare();
  reconstruction_ = std::move(reconstruction);
  last_job_failed_ = false;
  description_ = std::move(description);
  shown_request_ = last_request_;
  if (!shown_request_.edited_points) {
    // The ground truth of a 2D example stays with its edited samples.
    const shapes::Example* example = shapes::find_example(shown_request_.example);
    truth_example_ = example && example->dimension == 2 ? example->name : "";
  }
  message_ = "showing " + description_;
  const auto& stages = shown_stages();
  request_ = default_view(std::find(stages.begin(), stages.end(), request_.stage) != stages.end()
                              ? request_.stage
                              : scene::Stage::surface);
  playing_ = false;
  if (!same_dimension || !same_input) camera_fitted_ = false;
  scene_dirty_ = true;
}

const std::vector<scene::Stage>& Viewer::shown_stages() const {
  if (!reconstruction_) return scene::stages_of(method_at(method_), 3);
  return std::visit(
      [](const auto& r) -> const std::vector<scene::Stage>& {
        return scene::stages_of(r.options.method, r.dimension);
      },
      *reconstruction_);
}

bool Viewer::set_stage(scene::Stage stage) {
  const auto& stages = shown_stages();
  if (std::find(stages.begin(), stages.end(), stage) == stages.end()) {
    std::string names;
    for (scene::Stage s : stages)
      names += (names.empty() ? "" : ", ") + std::string(scene::stage_id(s));
    message_ = std::string("this method has no stage '") + scene::stage_id(stage) +
               "' (its stages: " + names + ")";
    return false;
  }
  explore();
  // Another stage starts whole: a step of one replay means nothing in another.
  if (request_.stage != stage) {
    request_.step = -1;
    playing_ = false;
  }
  request_.stage = stage;
  scene_dirty_ = true;
  follow_latest_event();
  return true;
}

void Viewer::step_stage(int delta) {
  const auto& stages = shown_stages();
  int index =
      static_cast<int>(std::find(stages.begin(), stages.end(), request_.stage) - stages.begin());
  index = std::clamp(index + delta, 0, static_cast<int>(stages.size()) - 1);
  set_stage(stages[index]);
}

// Selects a sample (focus_sample) or a pole (focus_pole); -1 clears. An index the shown
// reconstruction does not have is refused with a message.
bool Viewer::pick(int index, bool sample) {
  const std::size_t count =
      reconstruction_ ? (sample ? sample_count : pole_count)(*reconstruction_) : 0;
  if (index >= 0 && std::size_t(index) >= count) {
    message_ = std::string(sample ? "no sample " : "no pole ") + std::to_string(index) +
               (reconstruction_ ? " (there are " + std::to_string(count) + ")"
                                : " (nothing reconstructed yet)");
    return false;
  }
  explore();
  request_.focus_sample = sample ? index : -1;
  request_.focus_pole = sample ? -1 : index;
  scene_dirty_ = true;
  return true;
}

void Viewer::orbit_camera(float yaw_degrees, float pitch_degrees) {
  camera_move_.reset();
  camera_is_panel_camera_ = false;
  camera_.orbit(glm::radians(yaw_degrees), glm::radians(pitch_degrees));
}

void Viewer::pan_camera(float right, float up) {
  camera_move_.reset();
  camera_is_panel_camera_ = false;
  camera_.pan(right, up);
}

void Viewer::zoom_camera(float factor) {
  camera_move_.reset();
  camera_is_panel_camera_ = false;
  camera_.zoom(factor);
}

void Viewer::set_section(const scene::Clip& plane) {
  request_.sectioned = true;
  request_.clip = plane;
  scene_dirty_ = true;
  look_along_the_section();
}

void Viewer::look_along_the_section() {
  camera_move_.reset();
  camera_is_panel_camera_ = false;
  std::tie(camera_.yaw, camera_.pitch) = render::yaw_pitch_along(scene::normal_of(request_.clip));
}

void Viewer::reset_camera() {
  camera_fitted_ = false;
  camera_move_.reset();
  // On a tour panel, the panel's own camera.
  panel_camera_pending_ = tour_.active() && !tour_.exploring();
}

int Viewer::shown_dimension() const {
  return reconstruction_ ? dimension_of(*reconstruction_) : 0;
}

void Viewer::rebuild_scene() {
  if (!scene_dirty_ || !reconstruction_) return;
  scene_dirty_ = false;
  try {
    scene::Request request = request_;
    request.colour_blind = colour_blind_;
    scene::Scene scene =
        std::visit([&](const auto& r) { return scene::build_scene(r, request); }, *reconstruction_);
    add_true_curve(scene);
    renderer_->set_scene(scene);
    const float aspect = frame_height_ > 0
                             ? float(view_width(frame_width_)) / float(view_height(frame_height_))
                             : 1.0f;
    if (panel_camera_pending_) {
      // The panel's camera, as the gallery frames it (fitted to the samples, which every stage
      // shares, and stepped back for the legend when the picture draws one), flown to when the
      // reconstruction stays the same.
      const frontend::Shot& shot = tour_.image().shot;
      render::Camera target = render::fit(scene, aspect, shot.zoom, shot.yaw, shot.pitch);
      if (presenting_ && shot.zoom >= 1 && frame_height_ > 0) target = with_legend_room(target);
      if (walk_stages_ && camera_fitted_ && camera_.dimension == target.dimension) {
        camera_move_ = Camera_move{camera_, target, 0.0f};
      } else {
        camera_ = target;
      }
      panel_camera_pending_ = false;
      camera_is_panel_camera_ = camera_fitted_ = true;
    } else if (!camera_fitted_) {
      camera_ = render::fit(scene, aspect);
      camera_fitted_ = true;
      legend_room_pending_ = true;
    }
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
  }
}

void Viewer::frame(int width, int height, double seconds) {
  frame_width_ = width;
  frame_height_ = height;
  take_finished_job();
  // Edits made while a reconstruction ran: the newest points, once it has ended (a drag
  // reconstructs as fast as the reconstructions come, never queueing them).
  if (edits_pending_ && editor_.active() && !job_->running() && !job_->outcome_waiting())
    reconstruct_edits();
  advance_playback(seconds);
  advance_move_to_panel(seconds);
  advance_compare();
  handle_input(width, height);
  draw_menu();
  if (!presenting_) draw_panel(height);
  draw_caption(width, height);
  if (show_help_) draw_help();
  if (presenting_ != was_presenting_) {
    // The picture changed shape: framed afresh (a fit for the narrow view beside the panel is
    // far too small in the whole window), with room for the legend; a figure's panel keeps the
    // camera its gallery picture has.
    if (reconstruction_ && camera_is_panel_camera_) {
      panel_camera_pending_ = true;  // the gallery's framing, for the picture's new shape
      scene_dirty_ = true;
    } else if (reconstruction_) {
      if (comparing()) {
        refit_for_views();  // each view's shape, not the whole picture's
      } else {
        camera_fitted_ = false;
        scene_dirty_ = true;
      }
    }
    legend_room_pending_ = presenting_ && !camera_is_panel_camera_;
    was_presenting_ = presenting_;
  }
  if (scene_dirty_) compare_scenes_stale();
  rebuild_scene();
  if (legend_room_pending_ && presenting_ && !comparing()) leave_room_for_legend();
  legend_room_pending_ = false;
  if (reconstruction_ && !comparing()) draw_off_screen_markers(width, height);
  if (last_job_failed_) draw_failure_notice(width, height);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (reconstruction_) {
    render::Draw_options options;
    // The panel shows the legend and the title; presenting, the picture shows the legend.
    options.legend = presenting_;
    options.title = false;
    options.picture_scale = picture_scale_;
    options.hidden_layers = hidden_layers_;
    // The picture takes the window right of the panel, above the figure's caption.
    options.viewport_x = int(panel_width());
    options.viewport_y = caption_height_ + reserved_height_;
    if (comparing()) {
      draw_compare(width, height);
    } else {
      picture_cache_.draw(*renderer_, camera_, view_width(width), view_height(height), options);
    }
  }
}

// Presenting, the legend is drawn in the picture: a camera just fitted steps back, a little at a
// time, until a corner of the picture is clear of data for it (render::with_room_for_legend: the
// shape keeps at least 70% of its fitted size; a camera the user moved is left where it is).
void Viewer::leave_room_for_legend() {
  if (!reconstruction_ || frame_height_ <= 0) return;
  camera_ = with_legend_room(camera_);
}

render::Camera Viewer::with_legend_room(const render::Camera& camera) const {
  render::Draw_options options;
  options.title = false;
  options.picture_scale = picture_scale_;
  options.hidden_layers = hidden_layers_;
  options.legend = true;
  return render::with_room_for_legend(renderer_->legend(), camera, view_width(frame_width_),
                                      view_height(frame_height_), options);
}

int Viewer::view_height(int window_height) const {
  return std::max(1, window_height - caption_height_ - reserved_height_ - menu_bar_height_);
}

}  // namespace sculpt::viewer
