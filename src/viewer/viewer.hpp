// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's state and one frame of it: the reconstruction being shown, the stage and
// propagation step, the camera, layer visibility, the selection, the tour of the paper's
// figures, and the ImGui panels. Scripted runs (tests) drive the same object through Script.
#pragma once

#include <algorithm>
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "figures/cgal_meshes.hpp"
#include "point_editor.hpp"
#include "reconstruction_job.hpp"
#include "render/camera.hpp"
#include "render/picture_cache.hpp"
#include "render/picture_renderer.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "tour.hpp"

namespace sculpt::viewer {

class Viewer {
 public:
  Viewer();

  // The panel's width: 360 pixels at the normal text size, wider as the text is scaled up; none
  // while presenting. The picture takes the window right of it (view_width).
  float panel_width() const;
  int view_width(int window_width) const;

  // Presentation mode (F5, the View menu, --present, script `present on|off`): the panel hides
  // and the picture, with its legend drawn in it, takes the whole window.
  void set_presenting(bool on) { presenting_ = on; }
  bool presenting() const { return presenting_; }
  // One scale for the picture's points, lines and arrows (a projector: 2), --picture-scale,
  // from smallest_picture_scale to largest_picture_scale.
  static constexpr float smallest_picture_scale = 0.5f, largest_picture_scale = 4.0f;
  void set_picture_scale(float scale) { picture_scale_ = scale; }
  float picture_scale() const { return picture_scale_; }

  // Reconstruction inputs; each starts a background job.
  // An example is reconstructed as its own kind (bordered or closed), unless one is forced.
  void open_example(const std::string& name, Surface_kind kind = Surface_kind::automatic);
  void open_file(const std::string& path);
  void rerun();  // same input, current options
  // Reconstructs the loaded input again with another method ("crust", "paper", ...), keeping
  // the camera; false, with a message, for an unknown method or nothing loaded.
  bool switch_method(const std::string& name);
  // The same with the samples cleaned first or not: a name of cleaning_choices() (the panel's
  // combo).
  bool switch_cleaning(const std::string& name);
  // The kind files are reconstructed as (--closed, --bordered; else automatic).
  void set_file_kind(Surface_kind kind) { kind_ = file_kind_ = kind; }
  Surface_kind file_kind() const { return file_kind_; }
  void set_merge_duplicates(bool merge) { merge_duplicates_ = merge; }
  void set_method(Method method) {
    const auto& names = method_names();
    method_ = static_cast<int>(
        std::find_if(names.begin(), names.end(),
                     [&](const char* name) { return std::string(name) == to_string(method); }) -
        names.begin());
  }

  // What the student changes by hand; during the tour, each leaves the panel to explore.
  bool set_stage(scene::Stage stage);  // false, with a message, if the method has no such stage
  void step_stage(int delta);
  void set_step(long events);  // propagation events shown; -1 = all
  // 3D: cut away what lies beyond a plane (scene::Clip), or show everything again.
  void set_clip(const scene::Clip& clip) {
    request_.clipped = true;
    request_.clip = clip;
    scene_dirty_ = true;
  }
  void clear_clip() {
    request_.clipped = false;
    scene_dirty_ = true;
  }
  // 3D: draw the stage in section at a plane (scene::Request::sectioned), the camera turned to
  // look along its normal; or back to the stage whole.
  void set_section(const scene::Clip& plane);
  void look_along_the_section();  // the camera turned to look along the plane's normal
  // The colour-blind-safe colours (scene/colours.hpp), or the paper's: a preference of the
  // viewer, kept across reconstructions and tour panels.
  void set_colour_blind(bool on) {
    colour_blind_ = on;
    scene_dirty_ = true;
  }
  bool colour_blind() const { return colour_blind_; }
  void clear_section() {
    request_.sectioned = false;
    scene_dirty_ = true;
  }
  // Only what lies near the picked sample (scene::Request::neighbourhood).
  void set_neighbourhood(bool on) {
    request_.neighbourhood = on;
    scene_dirty_ = true;
    camera_fitted_ = false;  // to the neighbourhood, or back to the whole
  }
  // 3D: the polar balls too, every `every`-th (0: none).
  void show_polar_balls(int every) {
    request_.polar_balls = every > 0;
    request_.ball_every = std::max(1, every);
    scene_dirty_ = true;
  }
  // Each returns false, with a message, when the shown reconstruction has no such sample or pole.
  bool pick_sample(int sample) { return pick(sample, true); }  // -1 clears the selection
  bool pick_pole(int pole) { return pick(pole, false); }
  void reset_camera();
  // Moves the camera as the mouse would: orbit by angles in degrees (3D), pan by shares of the
  // visible half height, zoom by a factor (< 1 zooms in).
  void orbit_camera(float yaw_degrees, float pitch_degrees);
  void pan_camera(float right, float up);
  void zoom_camera(float factor);

  // Live editing of 2D samples (the Edit samples panel, the mouse, scripts): each edit
  // reconstructs the edited points with the method chosen. Each returns false, with a message,
  // for 3D, nothing shown, an index out of range or a sample already there.
  bool add_point(const Point<2>& p);
  bool move_point(int sample, const Point<2>& to);
  bool delete_point(int sample);
  // A drawn stroke becomes samples `spacing` apart (a share of the samples' box diagonal).
  bool add_stroke(const std::vector<Point<2>>& stroke, double spacing);
  bool undo_edit();
  bool save_points(const std::string& path);  // the samples shown, edited or not, as .xy
  void set_editing(bool on) { editing_ = on; }
  // The replay keeps the pole just labelled in view (on by default).
  void set_follow(bool on) { follow_ = on; }
  // Shows or hides a layer of the stage by id ("voronoi", "true-curve", ...).
  bool set_layer_visible(const std::string& id, bool visible);

  // The tour of the paper's figures (Paper menu, --figure, script commands). Each returns false,
  // with a message, when there is no such figure or panel.
  bool open_figure(const std::string& id, std::size_t panel = 0);
  bool go_to_panel(const std::string& panel);  // "next", "previous", "3" (1-based), "c"
  bool next_figure();
  bool previous_figure();
  void return_to_panel();  // after exploring: the panel as the figure shows it
  void close_tour();
  // "fig06c" while that panel is on screen as the figure shows it; "" otherwise.
  std::string panel_on_screen() const;
  void set_animation(bool on) { animate_ = on; }  // camera and stage moves between panels

  void press_key(int key);  // a GLFW key, as if pressed (scripts)
  // A lesson runs (App): Page Down and Page Up are its, not the tour's.
  void set_lesson_running(bool running) { lesson_running_ = running; }
  // The keys pressed since the last frame (GLFW key codes, a held key's repeats too), each acted
  // on once, however short the press.
  void set_key_presses(std::vector<int> keys) { key_presses_ = std::move(keys); }
  // Pixels along the window's bottom that another window takes (App's lesson), under the picture
  // and the tour's caption.
  void set_reserved_height(int pixels) { reserved_height_ = std::max(0, pixels); }

  // A reconstruction runs, has ended and its result is not shown yet, or the view is still
  // moving to a tour panel.
  bool busy() const {
    return job_->running() || job_->outcome_waiting() || moving_to_panel() || edits_pending_ ||
           compare_busy();
  }
  void cancel() { job_->request_cancel(); }
  bool reconstructing() const { return job_->running(); }
  const std::string& message() const { return message_; }
  bool has_reconstruction() const { return reconstruction_ != nullptr; }
  // Whether the last reconstruction asked for failed (a bad file): what is shown is older.
  bool last_job_failed() const { return last_job_failed_; }
  // The shown reconstruction's dimension (0 before any), whether its method has a replay (of
  // the labelling or the carving), and the picked sample (-1: none).
  int shown_dimension() const;
  bool has_replay() const;
  // Shows a stage that replays (propagation, carving, candidates, front, alpha) from its start and
  // plays it, at `pace` steps a second (0: the labelling at the pace set, a carving in about ten
  // seconds); false with a message when the method has no such stage or it does not replay.
  bool start_replay(scene::Stage stage, float pace = 0);
  bool replay_playing() const { return playing_; }
  void pause_replay() { playing_ = false; }
  int picked_sample() const { return request_.focus_sample; }
  scene::Stage stage() const { return request_.stage; }
  // The Explanation panel's paragraph for the stage on screen ("" before any reconstruction).
  std::string explanation() const;
  // The shown reconstruction's statistics as one line of JSON ("" before any).
  std::string statistics_line() const;

  // One frame: take a finished job, handle the mouse and keys, build the panels, draw.
  void frame(int width, int height, double seconds_since_last_frame);

  // A picture of the view (without the panel) at a chosen size, drawn as the figures are.
  bool export_picture(const std::string& path, int width, int height);
  // An animated WebP of the replay (at the propagation stage, in `frames` pictures) or else of
  // the method's stages.
  bool export_animation(const std::string& path, int width, int height, int frames = 60);
  bool save_camera(const std::string& path);
  bool load_camera(const std::string& path);
  // The result: a surface as .ply .obj .stl .off, a curve as .obj .svg (as `sculpt reconstruct`
  // writes them: vertex i is sample i).
  bool save_result(const std::string& path);

  // The view on screen as options that open it again (viewer_link.cpp): example, method, kind,
  // stage, step, sample; or figure and panel on a tour panel. Empty, with why, for a file or
  // edited samples (they exist only here) and before any reconstruction.
  std::vector<std::pair<std::string, std::string>> view_options(std::string& why_not) const;
  // Those options as a link to the page (browser) or a sculpt-view command line (desktop).
  std::string link_to_view(std::string& why_not) const;
  void copy_link_to_view();  // to the clipboard, and shown in the message

  bool wants_to_quit() const { return quit_; }
  bool animating() const { return playing_ || job_->running() || compare_busy(); }

  // Side by side (viewer_compare.cpp): two to four methods on the points shown, each in a view
  // with its verdict, one camera for all; false, with a message, for fewer or more or nothing
  // shown. Opening other points ends it, as stop_compare does.
  bool start_compare(const std::vector<Method>& methods);
  void stop_compare();
  bool comparing() const;

 private:
  struct Compared;
  struct Compare_state {
    Compare_state();
    ~Compare_state();
    std::vector<std::unique_ptr<Compared>> views;
    std::size_t next = 0;  // the first view whose reconstruction has not come
    std::unique_ptr<Reconstruction_job> job;
  };
  Compare_state compare_;
  bool compare_busy() const;
  void advance_compare();
  void draw_compare(int width, int height);
  void compare_scenes_stale();
  void refit_for_views();

  bool pick(int index, bool sample);
  // A picture, or an animation ("replay" or "stages", in `frames` pictures), of the view: the
  // shown reconstruction drawn into a framebuffer of the window's context.
  bool export_shot(const std::string& path, int width, int height, const std::string& animate,
                   int frames);
  // The stages of the shown reconstruction's method (or of the chosen one, before any).
  const std::vector<scene::Stage>& shown_stages() const;
  Job_request with_options(Job_request request) const;  // the options chosen in the panel
  void start_job(Job_request request);
  void take_finished_job();
  void show(std::shared_ptr<const Any_reconstruction> reconstruction, std::string description);
  void rebuild_scene();
  void handle_input(int width, int height);
  void on_key(int key);
  void advance_playback(double seconds);
  void click(glm::vec2 mouse, int width, int height);
  // Editing: the shown samples become the editor's (2D only); an edit's outcome; the mouse.
  bool begin_editing();
  void stop_editing();  // another input: the edits, a pending one, a drag or stroke forgotten
  bool edited(bool succeeded);
  void reconstruct_edits();
  bool handle_editing_input(int width, int height);  // true when the mouse was used to edit
  Point<2> world_at(glm::vec2 mouse, int width, int height) const;
  void add_true_curve(scene::Scene& scene) const;
  // Following the replay (viewer_follow.cpp): what the stage points at, the camera kept on it,
  // arrows at the edge to what lies outside the view.
  struct Point_of_interest {
    glm::vec3 at;
    std::string label;
  };
  std::vector<Point_of_interest> points_of_interest() const;
  void follow_latest_event();
  void draw_off_screen_markers(int width, int height);
  int view_height(int window_height) const;

  // The tour: load the panel's reconstruction (a job, unless it is shown or recent), then move
  // the stage, step and camera to the panel's.
  void show_tour_panel();
  void move_to_panel_view();
  void arrive_at_panel();
  void explore();  // the student changed the view by hand
  void advance_move_to_panel(double seconds);
  bool moving_to_panel() const {
    return panel_pending_ || !stage_walk_.empty() || camera_move_ || play_until_ >= 0;
  }

  void draw_menu();
  void draw_file_fields();
  void draw_download_items();
  // A file name for what is shown: "torus-paper-poles" and the extension.
  std::string download_name(const std::string& extension) const;
  // Whether a save may write `path` (not a folder, not a file this session opened); if not, the
  // reason is on screen.
  bool can_save_to(const std::string& path);
  void draw_paper_menu();
  void draw_caption(int width, int height);
  void draw_panel(int height);
  void draw_stepper();
  void draw_propagation_controls();
  void draw_pseudo_code();
  void draw_verdict();
  void draw_explanation();
  void draw_statistics();
  void draw_layers();
  void draw_clip_controls();
  void draw_editing_controls();
  void draw_selection();
  void draw_help();
  // A reconstruction or file that failed, said in the picture, where it cannot be missed.
  void draw_failure_notice(int width, int height);

  // The steps of the replay on screen (the labelling's events, the carving's steps), counted
  // once per reconstruction and stage.
  long event_count() const;
  long shown_step() const;  // the replay's step shown (-1 read as the stage's own end)
  const Labelling_event* latest_event() const;
  mutable std::weak_ptr<const Any_reconstruction> counted_reconstruction_;
  mutable scene::Stage counted_stage_ = scene::Stage::samples;
  mutable long counted_events_ = 0;

  std::unique_ptr<render::Renderer> renderer_;
  render::Picture_cache picture_cache_;  // the picture, drawn again only when it changes
  std::unique_ptr<render::Picture_renderer> picture_renderer_;  // exports, made at the first
  std::unique_ptr<Reconstruction_job> job_ = make_reconstruction_job();
  Job_request last_request_;
  std::shared_ptr<const Any_reconstruction> reconstruction_;
  std::string description_;
  Job_request shown_request_;  // the input and options of the reconstruction shown
  // The last few reconstructions, so a tour can go back and forth without recomputing.
  struct Recent {
    std::string key;
    std::shared_ptr<const Any_reconstruction> reconstruction;
    std::string description;
  };
  std::deque<Recent> recent_;
  scene::Request request_;
  bool scene_dirty_ = true;
  render::Camera camera_;
  bool colour_blind_ = false;  // the colour-blind palette (set_colour_blind)
  bool camera_fitted_ = false;
  std::vector<std::string> hidden_layers_;
  std::string message_;

  // Options for the next run.
  Surface_kind kind_ = Options{}.kind;
  Surface_kind file_kind_ = Options{}.kind;
  float box_factor_ = static_cast<float>(Options{}.box_factor);
  bool merge_duplicates_ = false;
  float alpha_ = static_cast<float>(Options{}.alpha);
  int rule_ = 0;      // auto, skin, extraction
  int cleaning_ = 0;  // an index of cleaning_names
  int method_ = 0;    // index in method_names()

  // Replay playback (the labelling, the carving).
  bool playing_ = false;
  float events_per_second_ = 20.0f;
  double playback_clock_ = 0;

  // The tour and the move to its panel: stages walked through one after another, the
  // propagation played up to the panel's step, the camera flown to the panel's.
  Tour tour_;
  figures::Cgal_meshes cgal_meshes_;
  bool animate_ = true;
  bool panel_pending_ = false;           // waiting for the panel's reconstruction
  bool walk_stages_ = false;             // same reconstruction as before: walk to the panel
  bool panel_camera_pending_ = false;    // fit the panel's camera once its scene is built
  bool camera_is_panel_camera_ = false;  // untouched since: pictures refit it to their size
  std::deque<scene::Stage> stage_walk_;
  double walk_clock_ = 0;
  long play_until_ = -1;
  double play_clock_ = 0;
  struct Camera_move {
    render::Camera from, to;
    float t = 0;
  };
  std::optional<Camera_move> camera_move_;
  int caption_height_ = 0;
  int menu_bar_height_ = 0;           // the picture starts below the main menu bar (draw_menu)
  bool legend_room_pending_ = false;  // a camera just fitted, or presentation just begun
  bool was_presenting_ = false;
  void leave_room_for_legend();
  // The camera stepped back until the legend drawn in the picture has a corner clear of data.
  render::Camera with_legend_room(const render::Camera& camera) const;
  int reserved_height_ = 0;
  std::string caption_figure_;  // the figure the caption's height was measured on
  float caption_min_height_ = 0;

  bool follow_ = true;  // the camera keeps the replay's pole just labelled in view
  // The camera as the replay last framed a far pole with the shape (render::follow_point).
  std::optional<render::Camera> far_framing_;
  int shown_code_line_ = -1;  // the pseudo-code line last marked, to scroll to a new one

  // Live 2D editing.
  Point_editor editor_;
  bool editing_ = false;        // the mouse adds, drags and deletes samples
  bool edits_pending_ = false;  // edited since the last reconstruction started
  int dragged_sample_ = -1;
  std::vector<Point<2>> stroke_;  // a stroke being drawn, in the plane
  std::vector<std::array<float, 2>> stroke_on_screen_;
  float stroke_spacing_ = 0.03f;  // a share of the samples' box diagonal
  bool show_true_curve_ = false;  // the curve a 2D example was sampled from
  std::string truth_example_;     // that example's name ("" for a file)

  // Panels.
  char path_field_[1024] = "";
  char camera_field_[1024] = "camera.json";
  char picture_field_[1024] = "sculpt.png";
  char points_field_[1024] = "points.xy";
  char animation_field_[1024] = "sculpt.webp";
  char result_field_[1024] = "sculpt.ply";
  int picture_size_[2] = {1600, 1200};
  bool show_help_ = false;
  bool lesson_running_ = false;
  bool last_job_failed_ = false;
  bool presenting_ = false;
  float picture_scale_ = 1.0f;
  std::vector<int> key_presses_;
  bool quit_ = false;
  int frame_width_ = 0, frame_height_ = 0;
};

}  // namespace sculpt::viewer
