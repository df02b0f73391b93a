// The viewer's state and one frame of it: the reconstruction being shown, the stage and
// propagation step, the camera, layer visibility, the selection, and the ImGui panels.
// Scripted runs (tests) drive the same object through Script.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reconstruction_job.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace sculpt::viewer {

class Viewer {
 public:
  Viewer();

  // Reconstruction inputs; each starts a background job.
  void open_example(const std::string& name);
  void open_file(const std::string& path);
  void rerun();  // same input, current options
  void set_bordered(bool bordered) { bordered_ = bordered; }
  void set_method(Method method) {
    const auto& names = method_names();
    method_ = static_cast<int>(
        std::find_if(names.begin(), names.end(),
                     [&](const char* name) { return std::string(name) == to_string(method); }) -
        names.begin());
  }

  void set_stage(scene::Stage stage);
  void step_stage(int delta);
  void set_step(long events);  // propagation events shown; -1 = all
  void pick_sample(int sample);
  void pick_pole(int pole);
  void reset_camera();

  // A reconstruction runs, or has ended and its result is not shown yet.
  bool busy() const { return job_.running() || job_.outcome_waiting(); }
  void cancel() { job_.request_cancel(); }
  const std::string& message() const { return message_; }
  bool has_reconstruction() const { return reconstruction_.has_value(); }
  scene::Stage stage() const { return request_.stage; }

  // One frame: take a finished job, handle the mouse and keys, build the panels, draw.
  void frame(int width, int height, double seconds_since_last_frame);

  // Headless snapshot through `sculpt render` (the figures' renderer), at a chosen size.
  bool export_picture(const std::string& path, int width, int height);
  bool save_camera(const std::string& path);
  bool load_camera(const std::string& path);

  bool wants_to_quit() const { return quit_; }
  bool animating() const { return playing_ || job_.running(); }

 private:
  void start_job(Job_request request);
  void take_finished_job();
  void rebuild_scene();
  void handle_input(int width, int height);
  void advance_playback(double seconds);
  void click(glm::vec2 mouse, int width, int height);

  void draw_menu();
  void draw_panel(int height);
  void draw_stepper();
  void draw_propagation_controls();
  void draw_pseudo_code();
  void draw_statistics();
  void draw_layers();
  void draw_selection();
  void draw_help();

  long event_count() const;
  const Labelling_event* latest_event() const;

  std::unique_ptr<render::Renderer> renderer_;
  Reconstruction_job job_;
  Job_request last_request_;
  std::optional<Any_reconstruction> reconstruction_;
  std::string description_;
  scene::Request request_;
  bool scene_dirty_ = true;
  render::Camera camera_;
  bool camera_fitted_ = false;
  std::vector<std::string> hidden_layers_;
  std::string message_;

  // Options for the next run.
  bool bordered_ = false;
  float box_factor_ = static_cast<float>(Options{}.box_factor);
  int rule_ = 0;    // auto, skin, extraction
  int method_ = 0;  // index in method_names()

  // Propagation playback.
  bool playing_ = false;
  float events_per_second_ = 20.0f;
  double playback_clock_ = 0;

  // Panels.
  char path_field_[1024] = "";
  char camera_field_[1024] = "camera.json";
  char picture_field_[1024] = "sculpt.png";
  int picture_size_[2] = {1600, 1200};
  bool show_help_ = false;
  bool quit_ = false;
  int frame_width_ = 0, frame_height_ = 0;
};

}  // namespace sculpt::viewer
