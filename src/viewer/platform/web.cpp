// SPDX-License-Identifier: GPL-3.0-or-later
// The browser: Emscripten's GLFW on the page's canvas with a WebGL 2 context, frames called by
// the browser (requestAnimationFrame), files taken from the file picker or a drop and handed back
// as downloads, through the page's script (web/sculpt-page.js).
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "viewer/platform/platform.hpp"

namespace sculpt::viewer::platform {

namespace {

std::function<bool()> frame_function;
Page_commands page_commands;

long frames_drawn = 0;

void call_frame() {
  ++frames_drawn;
  if (!frame_function()) emscripten_cancel_main_loop();
}

// JavaScript below, which clang-format would reshape.
// clang-format off
EM_JS(void, download_file, (const char* path), {
  const name = UTF8ToString(path);
  const bytes = FS.readFile(name);
  FS.unlink(name);
  Module["sculptPage"].download(name.substring(name.lastIndexOf("/") + 1), bytes);
});

EM_JS(void, tell_page_started, (), { Module["sculptPage"].started(); });

EM_JS(void, open_file_picker, (), { Module["sculptPage"].chooseFile(); });

EM_JS(void, write_clipboard, (const char* text),
      { Module["sculptPage"].copyText(UTF8ToString(text)); });

EM_JS(char*, page_location, (), {
  const address = location.origin + location.pathname;
  const size = lengthBytesUTF8(address) + 1;
  const text = _malloc(size);
  stringToUTF8(address, text, size);
  return text;
});
// clang-format on

}  // namespace

GLFWwindow* open_window(int width, int height, std::string& error) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  // No multisampling: the picture has its own (render::Picture_cache), the panels need none.
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window = glfwCreateWindow(width, height, "Sculpt", nullptr, nullptr);
  if (!window) {
    error = "this browser gives the page no WebGL 2 context";
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  return window;
}

const char* imgui_glsl_version() {
  return "#version 300 es";
}

void run_main_loop(std::function<bool()> frame) {
  frame_function = std::move(frame);
  // 0: at the display's rate; false: return now, the page keeps the program alive.
  emscripten_set_main_loop(call_frame, 0, false);
  tell_page_started();
}

void take_events(GLFWwindow* window, bool) {
  // The canvas fills the page: its pixels follow the page's size (and the screen's density).
  double css_width = 0, css_height = 0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  const double density = emscripten_get_device_pixel_ratio();
  const int width = std::max(320, int(std::lround(css_width * density)));
  const int height = std::max(240, int(std::lround(css_height * density)));
  int current_width = 0, current_height = 0;
  glfwGetWindowSize(window, &current_width, &current_height);
  if (width != current_width || height != current_height) glfwSetWindowSize(window, width, height);
}

std::string output_path(const std::string& name) {
  std::error_code ignored;
  std::filesystem::create_directories("/downloads", ignored);
  return "/downloads/" + name;
}

void deliver_file(const std::string& path) {
  download_file(path.c_str());
}

bool has_file_picker() {
  return true;
}

void choose_file() {
  open_file_picker();
}

void copy_text(const std::string& text) {
  write_clipboard(text.c_str());
}

void set_page_commands(Page_commands commands) {
  page_commands = std::move(commands);
}

std::string page_address() {
  char* text = page_location();
  std::string address = text;
  std::free(text);
  return address;
}

}  // namespace sculpt::viewer::platform

// Called by web/sculpt-page.js.
extern "C" {

EMSCRIPTEN_KEEPALIVE void sculpt_open_file(const char* path) {
  if (sculpt::viewer::platform::page_commands.open_file)
    sculpt::viewer::platform::page_commands.open_file(path);
}

EMSCRIPTEN_KEEPALIVE void sculpt_run_script(const char* script) {
  if (sculpt::viewer::platform::page_commands.run_script)
    sculpt::viewer::platform::page_commands.run_script(script);
}

// Frames drawn since the start: how the tests see the page stay live during a reconstruction.
EMSCRIPTEN_KEEPALIVE double sculpt_frames_drawn() {
  return double(sculpt::viewer::platform::frames_drawn);
}

EMSCRIPTEN_KEEPALIVE int sculpt_script_state() {
  const auto& state = sculpt::viewer::platform::page_commands.script_state;
  return state ? state() : 0;
}

}  // extern "C"
