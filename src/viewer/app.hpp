// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's program around the Viewer: its window, Dear ImGui, the script that may drive it,
// and one frame of all of them. main.cpp makes it from the command line (in the browser, from
// the page's address) and hands its frames to the platform's main loop.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "script.hpp"
#include "viewer.hpp"

struct GLFWwindow;

namespace sculpt::viewer {

class App {
 public:
  // Sets up Dear ImGui on a window whose context is current; text at `font_scale`.
  App(GLFWwindow* window, float font_scale);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  Viewer& viewer() { return *viewer_; }
  // Drives the viewer by this script from the next frame on (replacing one that runs). A script
  // that ends the program (--script, --frames) closes the desktop's window at its end; others
  // (the first view asked for, a lesson, the page's) leave the viewer to the user.
  void run_script(Script script, bool ends_program) {
    script_ = std::move(script);
    script_ends_program_ = ends_program;
  }
  // Runs a shipped lesson (lessons.hpp) step by step; false if there is none of that name.
  bool start_lesson(const std::string& name);
  // The script's state: none ran, it runs, it ended well, a command failed, or (a lesson) it
  // waits at a picture for Next.
  enum class Script_state { none, running, succeeded, failed, paused };  // paused: a lesson's
  Script_state script_state() const;

  // One frame: events, the script's commands, the viewer, the panels drawn. False when the
  // program should end (the window closed, Quit, a desktop script at its end).
  bool frame();
  // 1 when a picture could not be saved or a script command failed, else 0.
  int exit_status() const;

 private:
  void draw_lesson();        // the narration and Next, while a lesson runs
  void draw_lessons_menu();  // appended to the viewer's menu bar

  GLFWwindow* window_;
  std::unique_ptr<Viewer> viewer_;
  std::vector<int> pressed_;  // the keys pressed since the last frame (GLFW key codes)
  std::optional<Script> script_;
  bool script_ends_program_ = false;
  std::string lesson_title_;
  Script_state finished_script_ = Script_state::none;
  double last_frame_ = 0;
  int status_ = 0;
};

}  // namespace sculpt::viewer
