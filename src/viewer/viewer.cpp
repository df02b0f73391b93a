#include "viewer.hpp"

// Our GL header before GLFW's keys: it must be the first to include GL/gl.h.
#include "render/gl.hpp"
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on
#include <imgui.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "frontend/explanations.hpp"
#include "frontend/pseudo_code.hpp"
#include "frontend/shots.hpp"
#include "render/framebuffer.hpp"
#include "io/atomic_file.hpp"
#include "picking.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::viewer {

float panel_width() {
  return 360.0f * std::max(1.0f, ImGui::GetIO().FontGlobalScale);
}

int view_width(int window_width) {
  return std::max(1, window_width - int(panel_width()));
}

namespace {

constexpr double stage_dwell_seconds = 0.25;      // each stage walked through on the way to a panel
constexpr float camera_move_seconds = 0.7f;       // the camera's flight to a panel's
constexpr double propagation_play_seconds = 1.5;  // playing the labelling up to a panel's step
constexpr std::size_t recent_reconstructions = 4;

const char* rule_names[] = {"auto", "skin", "extraction"};
// The methods in the order of method_names() (the default first).
Method method_at(int index) {
  Method method = Options{}.method;
  parse_method(method_names()[index], method);
  return method;
}

ImVec4 imgui_color(const scene::Color& c) {
  return ImVec4(c.r, c.g, c.b, 1.0f);
}

// What makes two reconstructions the same: their input and options.
std::string request_key(const Job_request& r) {
  return r.path + "|" + r.example + "|" + std::to_string(r.dimension) + "|" +
         to_string(r.options.method) + "|" + to_string(r.options.kind) + "|" +
         std::to_string(r.options.box_factor) + "|" + to_string(r.options.rule) + "|" +
         std::to_string(r.options.alpha) + "|" + std::to_string(r.merge_duplicates) + "|" +
         // Edited points are never the same twice: each edit makes a new set.
         std::to_string(reinterpret_cast<std::uintptr_t>(r.edited_points.get()));
}

int rule_index(const std::string& name) {
  for (int i = 0; i < 3; ++i) {
    if (name == rule_names[i]) return i;
  }
  return 0;
}

// A stage as it shows by default: no selection, every layer.
scene::Request default_view(scene::Stage stage) {
  scene::Request request;
  request.stage = stage;
  return request;
}

// Eases in and out, so the camera does not jerk at either end of its flight.
float smoothstep(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

}  // namespace

Viewer::Viewer() : renderer_(std::make_unique<render::Renderer>()) {}

// ---------------------------------------------------------------------------------------------
// Reconstructions

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
  kind_ = file_kind_;  // a file: as asked on the command line, else chosen from its samples
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

Job_request Viewer::with_options(Job_request request) const {
  request.options.method = method_at(method_);
  request.options.kind = kind_;
  request.options.box_factor = box_factor_;
  request.options.alpha = alpha_;
  request.merge_duplicates = merge_duplicates_;
  request.options.rule = rule_ == 1   ? Surface_rule::skin
                         : rule_ == 2 ? Surface_rule::extraction
                                      : Surface_rule::automatic;
  return request;
}

void Viewer::start_job(Job_request request) {
  request = with_options(std::move(request));
  last_request_ = request;
  message_ = "reconstructing " + (request.edited_points     ? "the edited samples"
                                  : request.example.empty() ? request.path
                                                            : "example " + request.example);
  job_.start(std::move(request));
}

void Viewer::take_finished_job() {
  auto outcome = job_.take_outcome();
  if (!outcome) return;
  if (!outcome->error.empty()) {
    message_ = outcome->error == "cancelled" ? "cancelled" : "error: " + outcome->error;
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
  reconstruction_ = std::move(reconstruction);
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

// ---------------------------------------------------------------------------------------------
// What is shown

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

void Viewer::set_step(long events) {
  explore();
  request_.step = events < 0 ? -1 : std::min(events, event_count());
  scene_dirty_ = true;
  follow_latest_event();
}

// The samples and poles of the shown reconstruction, to refuse a pick of one that is not there.
namespace {
std::size_t sample_count(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.stats.samples; }, r);
}
std::size_t pole_count(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.poles.poles.size(); }, r);
}
int dimension_of(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.stats.dimension; }, r);
}
}  // namespace

// A cut-away plane for the 3D stages that fill space: the cells in front of it go, so those
// behind are seen whole, in section.
void Viewer::draw_clip_controls() {
  if (!ImGui::CollapsingHeader("Look inside (3D)")) return;
  bool changed = false;
  if (ImGui::Checkbox("only near the picked sample", &request_.neighbourhood))
    set_neighbourhood(request_.neighbourhood);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "With a sample picked (click one): only the cells, edges, faces, poles and balls "
        "near it, its own Voronoi cell, poles and balls whole");
  if (ImGui::Checkbox("polar balls", &request_.polar_balls)) {
    changed = true;
    // A sample's inner ball is as large as the part it lies in: a score of them at first.
    if (request_.polar_balls && request_.ball_every == 1)
      request_.ball_every = std::max<int>(1, int(pole_count(*reconstruction_) / 20));
  }
  if (request_.polar_balls) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    changed |= ImGui::SliderInt("every", &request_.ball_every, 1, 500, "%d-th",
                                ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Thousands of balls hide one another: draw every k-th pole's");
  }
  changed |= ImGui::Checkbox("cut at a plane", &request_.clipped);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Leave out every cell, edge, face and ball whose centre lies beyond the "
        "plane, to see inside the Delaunay triangulation, the Voronoi diagram or "
        "the solid");
  if (request_.clipped) {
    auto& clip = request_.clip;
    changed |= ImGui::SliderFloat("position", &clip.position, 0.0f, 1.0f, "%.2f");
    changed |= ImGui::SliderFloat("azimuth", &clip.azimuth, -180.0f, 180.0f, "%.0f deg");
    changed |= ImGui::SliderFloat("elevation", &clip.elevation, -90.0f, 90.0f, "%.0f deg");
    changed |= ImGui::SliderFloat("slab", &clip.slab, 0.0f, 0.5f, clip.slab > 0 ? "%.2f" : "off");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Keep only a slab this thick before the plane (a share of the box): a "
          "section of the cells instead of a half");
  }
  if (changed) scene_dirty_ = true;
}

namespace {

// The paper's cube is a square in the plane.
const char* reason_name(Label_reason reason, int dimension) {
  return dimension == 2 && reason == Label_reason::inscribed_cube ? "inscribed square"
                                                                  : to_string(reason);
}
}  // namespace

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

void Viewer::reset_camera() {
  camera_fitted_ = false;
  camera_move_.reset();
  // On a tour panel, the panel's own camera.
  panel_camera_pending_ = tour_.active() && !tour_.exploring();
}

// ---------------------------------------------------------------------------------------------
// The tour of the paper's figures

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
    job_.abandon();  // a reconstruction for another panel is no longer wanted
    move_to_panel_view();
    return;
  }
  for (const Recent& recent : recent_) {
    if (recent.key != key) continue;
    job_.abandon();
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
  scene::Request request;
  scene::parse_stage(shot.stage, request.stage);
  request.step = shot.step;
  request.focus_sample = shot.focus_sample;
  request.focus_pole = shot.focus_pole;
  request.wireframe = shot.wireframe;
  request.smooth = shot.smooth;
  request.ball_every = shot.ball_every;
  request.layers = shot.layers;
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

long Viewer::event_count() const {
  if (!reconstruction_) return 0;
  return std::visit([](const auto& r) { return long(r.propagation.events.size()); },
                    *reconstruction_);
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

int Viewer::shown_dimension() const {
  return reconstruction_ ? dimension_of(*reconstruction_) : 0;
}

bool Viewer::has_replay() const {
  if (!reconstruction_) return false;
  const Options& options =
      std::visit([](const auto& r) -> const Options& { return r.options; }, *reconstruction_);
  return scene::has_stage(options.method, shown_dimension(), scene::Stage::propagation);
}

void Viewer::rebuild_scene() {
  if (!scene_dirty_ || !reconstruction_) return;
  scene_dirty_ = false;
  try {
    scene::Scene scene = std::visit([&](const auto& r) { return scene::build_scene(r, request_); },
                                    *reconstruction_);
    add_true_curve(scene);
    renderer_->set_scene(scene);
    const float aspect = frame_height_ > 0
                             ? float(view_width(frame_width_)) / float(view_height(frame_height_))
                             : 1.0f;
    if (panel_camera_pending_) {
      // The panel's camera, as the gallery frames it (fitted to the samples, which every stage
      // shares), flown to when the reconstruction stays the same.
      const frontend::Shot& shot = tour_.image().shot;
      const render::Camera target = render::fit(scene, aspect, shot.zoom, shot.yaw, shot.pitch);
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
    }
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// The frame

void Viewer::frame(int width, int height, double seconds) {
  frame_width_ = width;
  frame_height_ = height;
  take_finished_job();
  // Edits made while a reconstruction ran: the newest points, once it has ended (a drag
  // reconstructs as fast as the reconstructions come, never queueing them).
  if (edits_pending_ && editor_.active() && !job_.running() && !job_.outcome_waiting())
    reconstruct_edits();
  advance_playback(seconds);
  advance_move_to_panel(seconds);
  handle_input(width, height);
  draw_menu();
  draw_panel(height);
  draw_caption(width, height);
  if (show_help_) draw_help();
  rebuild_scene();
  if (reconstruction_) draw_off_screen_markers(width, height);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (reconstruction_) {
    render::Draw_options options;
    options.legend = options.title = false;  // the panel shows both
    options.hidden_layers = hidden_layers_;
    // The picture takes the window right of the panel, above the figure's caption.
    options.viewport_x = int(panel_width());
    options.viewport_y = caption_height_;
    renderer_->draw(camera_, view_width(width), view_height(height), options);
  }
}

int Viewer::view_height(int window_height) const {
  return std::max(1, window_height - caption_height_);
}

void Viewer::advance_playback(double seconds) {
  if (!playing_ || request_.stage != scene::Stage::propagation) return;
  playback_clock_ += seconds * events_per_second_;
  const long steps = long(playback_clock_);
  if (steps == 0) return;
  playback_clock_ -= double(steps);
  const long current = request_.step < 0 ? event_count() : request_.step;
  if (current >= event_count()) {
    playing_ = false;
    return;
  }
  set_step(current + steps);
}

void Viewer::handle_input(int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    for (int key : {GLFW_KEY_R,
                    GLFW_KEY_F,
                    GLFW_KEY_H,
                    GLFW_KEY_RIGHT,
                    GLFW_KEY_LEFT,
                    GLFW_KEY_SPACE,
                    GLFW_KEY_PERIOD,
                    GLFW_KEY_COMMA,
                    GLFW_KEY_P,
                    GLFW_KEY_PAGE_DOWN,
                    GLFW_KEY_PAGE_UP,
                    GLFW_KEY_RIGHT_BRACKET,
                    GLFW_KEY_LEFT_BRACKET,
                    GLFW_KEY_T,
                    GLFW_KEY_ESCAPE,
                    GLFW_KEY_E,
                    GLFW_KEY_U,
                    GLFW_KEY_Z,
                    GLFW_KEY_DELETE,
                    GLFW_KEY_BACKSPACE}) {
      if (ImGui::IsKeyPressed(key)) on_key(key);
    }
  }
  if (io.WantCaptureMouse || !reconstruction_) return;
  if (editing_ && handle_editing_input(width, height)) return;

  const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  const float scale = 2.0f / float(view_height(height));
  const bool three = camera_.dimension == 3;
  const auto moved_by_hand = [&] {
    camera_move_.reset();
    camera_is_panel_camera_ = false;
  };
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    moved_by_hand();
    if (three) {
      camera_.orbit(-delta.x * 0.01f, delta.y * 0.01f);
    } else {
      camera_.pan(-delta.x * scale, delta.y * scale);
    }
  }
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
    moved_by_hand();
    camera_.pan(-delta.x * scale, delta.y * scale);
  }
  if (io.MouseWheel != 0) {
    moved_by_hand();
    camera_.zoom(std::pow(0.88f, io.MouseWheel));
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    if (drag.x * drag.x + drag.y * drag.y < 9.0f) {
      click({io.MousePos.x - panel_width(), io.MousePos.y}, view_width(width), view_height(height));
    }
  }
}

void Viewer::press_key(int key) {
  on_key(key);
}

void Viewer::on_key(int key) {
  const long shown = request_.step < 0 ? event_count() : request_.step;
  switch (key) {
    case GLFW_KEY_R:
    case GLFW_KEY_F:
      reset_camera(), scene_dirty_ = true;
      break;
    case GLFW_KEY_H:
      show_help_ = !show_help_;
      break;
    case GLFW_KEY_RIGHT:
      step_stage(+1);
      break;
    case GLFW_KEY_LEFT:
      step_stage(-1);
      break;
    case GLFW_KEY_SPACE:
      if (request_.stage == scene::Stage::propagation) explore(), playing_ = !playing_;
      break;
    case GLFW_KEY_PERIOD:
      set_step(shown + 1);
      break;
    case GLFW_KEY_COMMA:
      set_step(std::max(0L, shown - 1));
      break;
    case GLFW_KEY_P:
      export_picture(picture_field_, picture_size_[0], picture_size_[1]);
      break;
    // The tour; page keys are what presentation remotes send.
    case GLFW_KEY_PAGE_DOWN:
      go_to_panel("next");
      break;
    case GLFW_KEY_PAGE_UP:
      go_to_panel("previous");
      break;
    case GLFW_KEY_RIGHT_BRACKET:
      next_figure();
      break;
    case GLFW_KEY_LEFT_BRACKET:
      previous_figure();
      break;
    case GLFW_KEY_T:
      return_to_panel();
      break;
    case GLFW_KEY_ESCAPE:
      close_tour();
      break;
    case GLFW_KEY_E:
      editing_ = !editing_;
      if (editing_ && !begin_editing()) editing_ = false;
      break;
    case GLFW_KEY_U:
      undo_edit();
      break;
    case GLFW_KEY_Z:  // Ctrl+Z
      if (ImGui::GetIO().KeyCtrl) undo_edit();
      break;
    case GLFW_KEY_DELETE:
    case GLFW_KEY_BACKSPACE:
      if (editing_ && request_.focus_sample >= 0) delete_point(request_.focus_sample);
      break;
    default:
      break;
  }
}

// A click picks the nearest pole where poles are shown, else the nearest sample; elsewhere it
// clears the selection.
void Viewer::click(glm::vec2 mouse, int width, int height) {
  const glm::mat4 view_projection = camera_.projection(float(width) / height) * camera_.view();
  const glm::vec2 viewport(width, height);
  const bool poles_shown =
      request_.stage >= scene::Stage::poles && request_.stage <= scene::Stage::sculpted_delaunay;
  std::visit(
      [&](const auto& r) {
        constexpr int D = std::decay_t<decltype(r)>::dimension;
        int pole = -1;
        if (poles_shown) {
          std::vector<Point<D>> centers;
          for (const auto& p : r.poles.poles) centers.push_back(p.center);
          pole = pick_nearest<D>(centers, centers.size(), view_projection, mouse, viewport);
        }
        const int sample =
            pick_nearest<D>(r.sites, r.sample_count(), view_projection, mouse, viewport);
        if (sample >= 0) {
          pick_sample(sample);
        } else if (pole >= 0) {
          pick_pole(pole);
        } else {
          pick_sample(-1);
        }
      },
      *reconstruction_);
}

// ---------------------------------------------------------------------------------------------
// Files

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
      if (std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) ==
          hidden_layers_.end())
        shot.layers.push_back(layer.id);
    }
  }
  try {
    if (!picture_renderer_) picture_renderer_ = std::make_unique<render::Context_picture_renderer>();
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

// ---------------------------------------------------------------------------------------------
// Panels

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
  ImGui::SetNextWindowPos(ImVec2(panel_width(), float(height)), ImGuiCond_Always, ImVec2(0, 1));
  const float caption_max_height = 0.45f * float(height);
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(caption_width, std::min(caption_min_height_, caption_max_height)),
      ImVec2(caption_width, caption_max_height));
  ImGui::Begin("Paper", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushTextWrapPos(caption_width - ImGui::GetStyle().WindowPadding.x);
  const figures::Figure& figure = tour_.figure();
  const figures::Figure_image& image = tour_.image();

  const std::size_t count = figure.images.size();
  ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.2f, 1.0f), "%s", tour_.panel_name().c_str());
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

  ImGui::TextUnformatted(figure.caption.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.7f, 0.75f, 0.85f, 1.0f));
  ImGui::TextWrapped("Paper: \"%s\"", figure.sentence.c_str());
  ImGui::PopStyleColor();
  if (tour_.exploring()) {
    ImGui::TextWrapped(
        "Exploring from %s: every tool of the viewer works on this "
        "reconstruction. T (or the button above) returns to the panel.",
        tour_.panel_name().c_str());
  } else {
    ImGui::TextWrapped("%s%s. %s", image.suffix.empty() ? "" : ("(" + image.suffix + ") ").c_str(),
                       image.what.c_str(), image.why.c_str());
  }
  if (!figure.differences.empty()) {
    ImGui::TextDisabled("Differs from the paper (hover)");
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

void Viewer::draw_panel(int height) {
  const float top = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panel_width(), float(height) - top), ImGuiCond_Always);
  ImGui::Begin("Sculpt", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextWrapped("%s", message_.c_str());
  if (job_.running()) {  // not while the view merely moves to a tour panel
    // Across the whole reconstruction, naming the stage it is in.
    const auto status = job_.status();
    const std::string label =
        status.stage + " (" + std::to_string(int(100 * status.overall)) + "%)";
    ImGui::ProgressBar(float(status.overall), ImVec2(-70, 0), label.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancel();
  }
  if (ImGui::CollapsingHeader("Reconstruction options")) {
    // Choosing another method reconstructs the same input at once, the camera kept, so a class
    // can flip between methods on the same points.
    if (ImGui::Combo("method", &method_, method_names().data(),
                     static_cast<int>(method_names().size())) &&
        !job_.running() &&
        (!last_request_.path.empty() || !last_request_.example.empty() || editor_.active())) {
      rerun();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe(method_at(method_)));
    // Automatic: closed, unless the closed result spans openings and the bordered one has fewer
    // defects (the verdict line says which was kept).
    static const char* kinds[] = {"automatic", "closed", "bordered"};
    int kind = kind_ == Surface_kind::closed ? 1 : kind_ == Surface_kind::bordered ? 2 : 0;
    if (ImGui::Combo("kind", &kind, kinds, 3)) {
      kind_ = kind == 1   ? Surface_kind::closed
              : kind == 2 ? Surface_kind::bordered
                          : Surface_kind::automatic;
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "automatic: closed, unless the closed result spans openings and the bordered one is "
          "cleaner");
    }
    ImGui::Checkbox("merge repeated points", &merge_duplicates_);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Scans often repeat a few points: drop the copies instead of refusing the file");
    ImGui::SliderFloat("box factor", &box_factor_, 1.1f, 10.0f, "%.1f");
    if (method_at(method_) == Method::alpha_shape) {
      // One radius for the whole shape: the lesson of what it fills and what it leaves open.
      if (ImGui::InputFloat("alpha (0: chosen)", &alpha_, 0, 0, "%g"))
        alpha_ = std::max(alpha_, 0.0f);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The radius of the alpha shape, in the input's units; 0 takes the smallest "
            "whose solid is one piece holding every sample");
    }
    ImGui::Combo("surface rule", &rule_, rule_names, 3);
    if (ImGui::Button("Reconstruct again") && !busy() &&
        (!last_request_.path.empty() || !last_request_.example.empty() || editor_.active()))
      rerun();
  }
  if (reconstruction_) {
    draw_verdict();
    draw_stepper();
    if (dimension_of(*reconstruction_) == 3) draw_clip_controls();
    if (dimension_of(*reconstruction_) == 2) draw_editing_controls();
    if (request_.stage == scene::Stage::propagation) draw_propagation_controls();
    draw_explanation();
    draw_pseudo_code();
    draw_layers();
    draw_selection();
    draw_statistics();
  }
  ImGui::End();
}

void Viewer::draw_stepper() {
  ImGui::Separator();
  ImGui::TextUnformatted(scene::stage_title(request_.stage));
  const auto& stages = shown_stages();
  int index =
      static_cast<int>(std::find(stages.begin(), stages.end(), request_.stage) - stages.begin());
  if (ImGui::ArrowButton("##previous", ImGuiDir_Left)) step_stage(-1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(220);
  if (ImGui::SliderInt("##stage", &index, 0, static_cast<int>(stages.size()) - 1,
                       scene::stage_id(stages[index]))) {
    set_stage(stages[index]);
  }
  ImGui::SameLine();
  if (ImGui::ArrowButton("##next", ImGuiDir_Right)) step_stage(+1);
}

void Viewer::draw_propagation_controls() {
  const long total = event_count();
  int shown = int(request_.step < 0 ? total : request_.step);
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
  if (ImGui::SliderInt("event", &shown, 0, int(total))) set_step(shown);
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

std::string Viewer::explanation() const {
  if (!reconstruction_) return "";
  const Options& options =
      std::visit([](const auto& r) -> const Options& { return r.options; }, *reconstruction_);
  return frontend::explanation(options.method, options.kind, dimension_of(*reconstruction_),
                               request_.stage);
}

// What the stage on screen shows, why it matters and what to look for: open by default, so a
// class reads it with the picture.
void Viewer::draw_explanation() {
  if (!ImGui::CollapsingHeader("Explanation", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::PushTextWrapPos(0.0f);  // wrap at the panel's edge
  ImGui::TextUnformatted(explanation().c_str());
  ImGui::PopTextWrapPos();
}

void Viewer::draw_pseudo_code() {
  if (!ImGui::CollapsingHeader("Algorithm", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Options& options =
      std::visit([](const auto& r) -> const Options& { return r.options; }, *reconstruction_);
  const frontend::Pseudo_code& code =
      frontend::pseudo_code(options.method, options.kind, dimension_of(*reconstruction_));
  // A conflict offered right after the event on screen: its line, so the replay reaches it.
  const long shown = request_.step < 0 ? event_count() : request_.step;
  const bool conflict_now =
      std::visit([&](const auto& r) { return frontend::conflict_after(r.propagation, shown); },
                 *reconstruction_);
  const Labelling_event* latest = latest_event();
  const bool seed_partner = std::visit(
      [&](const auto& r) { return frontend::labels_seed_partner(r, latest); }, *reconstruction_);
  const int current =
      frontend::current_line(code, request_.stage, latest, conflict_now, seed_partner);
  // The statement's loops and continuation lines in a softer colour, the statement itself marked.
  const std::vector<int> lit =
      frontend::highlighted_lines(code, request_.stage, latest, conflict_now, seed_partner);
  const auto& lines = code.lines;
  // The code scrolls in a box of its own, at most 45% of the panel high (a projector's large
  // font): the running statement is scrolled into sight there, never the verdict and controls.
  const float all_lines = ImGui::GetTextLineHeightWithSpacing() * float(lines.size()) +
                          ImGui::GetStyle().WindowPadding.y;
  ImGui::BeginChild("pseudo-code",
                    ImVec2(0, std::min(all_lines, 0.45f * ImGui::GetWindowHeight())));
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    if (i == current) {
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.2f, 1.0f), "> %s", lines[i]);
      if (current != shown_code_line_ && !ImGui::IsItemVisible()) ImGui::SetScrollHereY(0.5f);
      shown_code_line_ = current;
    } else if (std::binary_search(lit.begin(), lit.end(), i)) {
      ImGui::TextColored(ImVec4(0.95f, 0.85f, 0.6f, 1.0f), "  %s", lines[i]);
    } else {
      ImGui::TextDisabled("  %s", lines[i]);
    }
  }
  ImGui::EndChild();
}

void Viewer::draw_layers() {
  if (!ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const auto& layer : renderer_->scene().layers) {
    ImGui::ColorButton(("##" + layer.id).c_str(), imgui_color(layer.color),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    // A light outline: dark swatches (the curve, the polar circles) show on the dark panel.
    ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                        IM_COL32(220, 220, 220, 255));
    ImGui::SameLine();
    bool visible =
        std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) == hidden_layers_.end();
    if (ImGui::Checkbox(layer.label.c_str(), &visible)) {
      explore();
      if (visible) {
        hidden_layers_.erase(std::remove(hidden_layers_.begin(), hidden_layers_.end(), layer.id),
                             hidden_layers_.end());
      } else {
        hidden_layers_.push_back(layer.id);
      }
    }
  }
}

void Viewer::draw_selection() {
  if (request_.focus_sample < 0 && request_.focus_pole < 0) return;
  if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::PushTextWrapPos(0.0f);  // long lines wrap at the panel's edge instead of being cut
  std::visit(
      [&](const auto& r) {
        const auto describe_pole = [&](int pole) {
          if (pole < 0) return;
          const auto& p = r.poles.poles[pole];
          ImGui::Text("pole %d: %s%s, radius %.4g", pole, to_string(r.propagation.labels[pole]),
                      p.convex ? ", convex" : "", p.radius);
          for (std::size_t i = 0; i < r.propagation.events.size(); ++i) {
            const auto& e = r.propagation.events[i];
            if (e.pole != pole) continue;
            if (e.source >= 0) {
              ImGui::Text("  labelled at event %zu by pole %d (%s)", i + 1, e.source,
                          reason_name(e.reason, r.stats.dimension));
            } else {
              ImGui::Text("  labelled at event %zu: %s", i + 1,
                          reason_name(e.reason, r.stats.dimension));
            }
          }
        };
        if (request_.focus_sample >= 0) {
          const int s = request_.focus_sample;
          ImGui::Text("sample %d", s);
          ImGui::TextDisabled("its Voronoi cell, poles, polar balls and inscribed %s are shown",
                              r.stats.dimension == 2 ? "squares" : "cubes");
          ImGui::TextUnformatted("p+:");
          describe_pole(r.poles.positive_pole[s]);
          ImGui::TextUnformatted("p-:");
          describe_pole(r.poles.negative_pole[s]);
        } else {
          describe_pole(request_.focus_pole);
        }
      },
      *reconstruction_);
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Clear selection")) pick_sample(-1);
}

// The truth about the result, green or red, at the top of the panel where it is always seen.
void Viewer::draw_verdict() {
  const Statistics& s =
      std::visit([](const auto& r) -> const Statistics& { return r.stats; }, *reconstruction_);
  const Verdict v = verdict(s);
  ImGui::PushStyleColor(ImGuiCol_Text,
                        v.manifold ? ImVec4(0.5f, 0.9f, 0.5f, 1) : ImVec4(1, 0.45f, 0.4f, 1));
  ImGui::TextWrapped("%s: %s", to_string(s.method), v.line.c_str());
  ImGui::PopStyleColor();
}

void Viewer::draw_statistics() {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Statistics& s =
      std::visit([](const auto& r) -> const Statistics& { return r.stats; }, *reconstruction_);
  const bool three = s.dimension == 3;
  ImGui::Text("%s", description_.c_str());
  if (s.kind_chosen_automatically) {
    if (s.closed_spanning_facets > 0) {
      ImGui::TextWrapped("kind: %s, chosen (closed spanned openings with %zu %s)",
                         to_string(s.kind), s.closed_spanning_facets,
                         three ? "triangles" : "edges");
    } else {
      ImGui::Text("kind: %s, chosen (no opening)", to_string(s.kind));
    }
  } else {
    ImGui::Text("kind: %s", to_string(s.kind));
  }
  if (sculpts(s.method)) {
    ImGui::Text("n %zu   poles %zu   m %zu", s.samples, s.poles, s.inserted_poles);
    ImGui::Text("%s %zu   unlabelled %zu", s.method == Method::paper ? "conflicts" : "contradicted",
                s.conflicts, s.unlabelled_poles);
  } else {
    ImGui::Text("n %zu   poles %zu", s.samples, s.poles);
  }
  if (s.method == Method::alpha_shape) ImGui::Text("alpha %g", s.alpha);
  if (s.spanning_facets > 0) ImGui::Text("triangles spanning openings %zu", s.spanning_facets);
  if (s.set_in_samples > 0) ImGui::Text("left-off samples set in %zu", s.set_in_samples);
  if (s.attached_samples > 0) ImGui::Text("left-off samples attached %zu", s.attached_samples);
  if (s.joined_pinches > 0) ImGui::Text("pinched fans joined %zu", s.joined_pinches);
  if (s.dropped_fans > 0) ImGui::Text("pinched fans dropped %zu", s.dropped_fans);
  if (s.closed_notches > 0) ImGui::Text("sharp border notches closed %zu", s.closed_notches);
  if (s.filled_gaps > 0) ImGui::Text("gaps in the sampling filled %zu", s.filled_gaps);
  if (s.torn_loops > 0) ImGui::Text("torn loops (not openings) %zu", s.torn_loops);
  if (s.candidate_facets > 0) {
    ImGui::Text("cells %zu   candidates %zu, pruned %zu%s", s.delaunay_cells, s.candidate_facets,
                s.pruned_facets, s.rims_kept ? " (rims kept)" : "");
  } else if (!sculpts(s.method)) {
    ImGui::Text("cells %zu", s.delaunay_cells);
  } else if (joins_neighbours(s.method, s.kind, s.dimension)) {
    ImGui::Text("cells %zu; the curves join nearest neighbours", s.delaunay_cells);
  } else if (inserts_poles(s.method, s.kind, s.dimension)) {
    ImGui::Text("cells %zu -> %zu   solid %zu", s.delaunay_cells, s.sculpted_cells, s.solid_cells);
  } else {
    if (s.carved_by_flood) {
      ImGui::Text("cells %zu, carved %zu in one flood", s.delaunay_cells, s.carved_cells);
    } else {
      ImGui::Text("cells %zu, carved %zu, outer kept %zu", s.delaunay_cells, s.carved_cells,
                  s.kept_outer_cells);
    }
    ImGui::Text("solid %zu", s.solid_cells);
  }
  ImGui::Text("%s %zu   %s %zu", three ? "triangles" : "edges", s.facets,
              three ? "border edges" : "end points", s.boundary_ridges);
  ImGui::Text("non-manifold %zu   unused %zu   pieces %zu", s.non_manifold_ridges, s.unused_samples,
              s.components);
  if (ImGui::TreeNode("time per stage")) {
    for (const auto& stage : s.stages)
      ImGui::Text("%-12s %8.3f s", stage.name.c_str(), stage.seconds);
    ImGui::Text("%-12s %8.3f s", "total", s.total_seconds);
    ImGui::TreePop();
  }
}

void Viewer::draw_help() {
  ImGui::SetNextWindowPos(ImVec2(panel_width() + 20, 40), ImGuiCond_FirstUseEver);
  ImGui::Begin("Controls", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(
      "left / right arrow   previous / next stage\n"
      "space                play / pause the pole separation\n"
      ", and .              one labelling event back / forward\n"
      "left drag            orbit (3D), pan (2D)\n"
      "right or middle drag pan\n"
      "wheel                zoom\n"
      "click                pick a sample or a pole\n"
      "E                    edit samples (2D): click adds, drag moves,\n"
      "                     right click or Delete removes, Shift+drag draws\n"
      "U or Ctrl+Z          undo the last edit\n"
      "R or F               fit and reset the camera\n"
      "Page Down / Page Up  paper tour: next / previous panel\n"
      "] and [              paper tour: next / previous figure\n"
      "T                    paper tour: back to the panel after exploring\n"
      "Esc                  close the paper tour\n"
      "P                    save a picture (File menu: path and size)\n"
      "H                    this help");
  ImGui::End();
}

}  // namespace sculpt::viewer
