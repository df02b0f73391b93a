// SPDX-License-Identifier: GPL-3.0-or-later
// clang-format off
// Our GL header first: it must be the first to include the platform's GL header.
#include "render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on
#include "app.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <iostream>
#include <utility>

#include "lessons.hpp"
#include "platform/platform.hpp"
#include "readable_style.hpp"
#include "render/image.hpp"

namespace sculpt::viewer {

namespace {

void on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
  if (count > 0 && viewer && !viewer->busy()) viewer->open_file(paths[0]);
}

// Every key press since the last frame, from GLFW's events. ImGui 1.86 reads keys as a state
// once a frame, so a tap whose press and release fall between two frames (a presentation
// remote's Page Down, on a slow software renderer) would be lost.
std::vector<int>& key_presses() {
  static std::vector<int> presses;
  return presses;
}

void on_key(GLFWwindow*, int key, int, int action, int) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT) key_presses().push_back(key);
}

}  // namespace

App::App(GLFWwindow* window, float font_scale) : window_(window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::GetIO().FontGlobalScale = font_scale;
  ImGui::StyleColorsDark();
  use_readable_colours(ImGui::GetStyle());
  // Ours first: ImGui's backend installs its own callback and calls the one it replaced.
  glfwSetKeyCallback(window, on_key);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init(platform::imgui_glsl_version());
  viewer_ = std::make_unique<Viewer>();
  glfwSetWindowUserPointer(window, viewer_.get());
  glfwSetDropCallback(window, on_drop);
  last_frame_ = glfwGetTime();
}

App::~App() {
  glfwSetWindowUserPointer(window_, nullptr);
  viewer_.reset();  // its GL objects go while the context still exists
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

App::Script_state App::script_state() const {
  if (script_) return script_->paused() ? Script_state::paused : Script_state::running;
  return finished_script_;
}

int App::exit_status() const {
  return status_ != 0 || (script_ && script_ends_program_ && script_->failed()) ? 1 : 0;
}

bool App::start_lesson(const std::string& name) {
  const Lesson* lesson = find_lesson(name);
  if (!lesson) return false;
  run_script(Script::from_text(lesson->script, Script::Mode::lesson), false);
  lesson_title_ = lesson_title(*lesson);
  return true;
}

// A strip along the bottom of the picture: the lesson's title, the narration of the step on
// screen, and Next (Page Down, what presentation remotes send) when it waits at a picture.
void App::draw_lesson() {
  if (!script_ || !script_->is_lesson()) {
    viewer_->set_reserved_height(0);
    return;
  }
  if (script_->paused() && !ImGui::GetIO().WantCaptureKeyboard &&
      std::count(pressed_.begin(), pressed_.end(), GLFW_KEY_PAGE_DOWN) > 0)
    script_->resume();
  // A strip along the bottom of the picture, which it takes from the picture (as the tour's
  // caption does), so that the narration never covers what it speaks of.
  const ImGuiViewport* view = ImGui::GetMainViewport();
  const float width = float(viewer_->view_width(int(view->Size.x)));
  ImGui::SetNextWindowPos(ImVec2(viewer_->panel_width(), view->Size.y), ImGuiCond_Always,
                          ImVec2(0, 1));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, 0.4f * view->Size.y));
  ImGui::Begin("Lesson", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushTextWrapPos(width - ImGui::GetStyle().WindowPadding.x);
  ImGui::TextColored(imgui_colour(panel_colours::current_line), "Lesson: %s",
                     lesson_title_.c_str());
  ImGui::TextDisabled("step %d of %d", std::min(script_->step(), script_->steps()),
                      script_->steps());
  ImGui::SameLine();
  if (script_->paused()) {
    if (ImGui::SmallButton("Next (Page Down)")) script_->resume();
  } else {
    ImGui::TextDisabled("(running)");
  }
  ImGui::SameLine();
  bool end = ImGui::SmallButton("End the lesson");
  ImGui::TextUnformatted(script_->narration().c_str());
  ImGui::PopTextWrapPos();
  viewer_->set_reserved_height(int(ImGui::GetWindowHeight()));
  ImGui::End();
  if (end) {
    script_.reset();
    finished_script_ = Script_state::succeeded;
    viewer_->set_reserved_height(0);
  }
}

void App::draw_lessons_menu() {
  if (!ImGui::BeginMainMenuBar()) return;  // appends to the viewer's menu bar
  if (ImGui::BeginMenu("Lessons")) {
    for (const Lesson& lesson : lessons()) {
      if (ImGui::MenuItem(lesson_title(lesson).c_str())) start_lesson(lesson.name);
    }
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

bool App::frame() {
  if (glfwWindowShouldClose(window_)) return false;
  // A page is not closed by a program: Quit and a script's end leave it open.
  if (viewer_->wants_to_quit() && !platform::in_browser) return false;
  // A script drives frames (a lesson waiting at a picture does not: the user does).
  platform::take_events(window_, (script_ && !script_->paused()) || viewer_->animating());
  // The presses since the last frame: from this poll on the desktop, from the page's events
  // between two animation frames in the browser.
  pressed_ = std::exchange(key_presses(), {});
  std::string screenshot;
  if (script_) {
    screenshot = script_->before_frame(*viewer_);
    if (script_->finished() && screenshot.empty()) {
      finished_script_ = script_->failed() ? Script_state::failed : Script_state::succeeded;
      // Only a script that is the program's run decides its exit status: a first view that
      // could not be shown said so on screen.
      if (script_->failed() && script_ends_program_) status_ = 1;
      script_.reset();
      if (script_ends_program_ && !platform::in_browser) return false;
    }
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  const double now = glfwGetTime();
  viewer_->set_lesson_running(script_ && script_->is_lesson());
  viewer_->set_key_presses(pressed_);
  viewer_->frame(width, height, now - last_frame_);
  last_frame_ = now;
  draw_lessons_menu();
  draw_lesson();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!screenshot.empty()) {
    try {
      render::write_png(screenshot, render::read_pixels(width, height));
      platform::deliver_file(screenshot);
    } catch (const std::exception& e) {
      std::cerr << "sculpt-view: " << e.what() << '\n';
      status_ = 1;
    }
  }
  glfwSwapBuffers(window_);
  return true;
}

}  // namespace sculpt::viewer
