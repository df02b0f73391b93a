// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop: a GLFW window with an OpenGL 3.3 core context, frames in a loop, files where the
// user names them.
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on

#include "viewer/platform/platform.hpp"

namespace sculpt::viewer::platform {

GLFWwindow* open_window(int width, int height, std::string& error) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // No multisampling: the picture has its own (render::Picture_cache), the panels need none.
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window = glfwCreateWindow(width, height, "Sculpt", nullptr, nullptr);
  if (!window) {
    error = "cannot open an OpenGL 3.3 window";
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  return window;
}

const char* imgui_glsl_version() {
  return "#version 330 core";
}

void run_main_loop(std::function<bool()> frame) {
  while (frame()) {
  }
}

void take_events(GLFWwindow*, bool animating) {
  if (animating) {
    glfwPollEvents();
  } else {
    glfwWaitEventsTimeout(0.1);
  }
}

std::string output_path(const std::string& name) {
  return name;
}

void deliver_file(const std::string&) {}

bool has_file_picker() {
  return false;
}

void choose_file() {}

void copy_text(const std::string& text) {
  glfwSetClipboardString(glfwGetCurrentContext(), text.c_str());
}

void set_page_commands(Page_commands) {}

std::string page_address() {
  return "";
}

}  // namespace sculpt::viewer::platform
