// SPDX-License-Identifier: GPL-3.0-or-later
// What differs between the desktop and the browser under the viewer, and nothing else: the
// window and its GL context, how frames are driven, how files reach the user and the clipboard.
// desktop.cpp implements it with GLFW on X11/Wayland, web.cpp in the browser (Emscripten's GLFW
// on a canvas, WebGL 2). The reconstruction job has its own runners (thread_job.cpp,
// worker_job.cpp).
#pragma once

#include <functional>
#include <string>

struct GLFWwindow;

namespace sculpt::viewer::platform {

#ifdef __EMSCRIPTEN__
inline constexpr bool in_browser = true;
#else
inline constexpr bool in_browser = false;
#endif

// A window of width x height with a GL context the renderer can use (OpenGL 3.3 core, or WebGL 2
// on the page's canvas), current; nullptr with the reason in `error`.
GLFWwindow* open_window(int width, int height, std::string& error);
// The #version line Dear ImGui's OpenGL backend compiles its shaders with.
const char* imgui_glsl_version();

// Calls `frame` for every frame until it returns false. On the desktop this returns then; in the
// browser it returns at once and the page calls `frame` at its refresh rate for as long as it is
// open (what `frame` needs must outlive this call).
void run_main_loop(std::function<bool()> frame);
// Before a frame: take the window's events (on the desktop, waiting up to a tenth of a second
// for one when nothing moves on screen); in the browser, size the canvas to the page.
void take_events(GLFWwindow* window, bool animating);

// Where to write a file the user asked for by name only: the current folder on the desktop; in
// the browser a folder of the page's memory, whence deliver_file hands it over.
std::string output_path(const std::string& name);
// A file the viewer has just written at `path`: on the desktop it stays there; in the browser it
// is handed to the user as a download named after it, and removed from the page's memory.
void deliver_file(const std::string& path);
// Whether files are chosen with the browser's file picker (choose_file) rather than typed.
bool has_file_picker();
// Opens the browser's file picker; the chosen file reaches the viewer as a dropped one does.
void choose_file();
// Puts text on the clipboard.
void copy_text(const std::string& text);
// What the page's script may ask of the program: open a file it wrote into the program's file
// system (the file picker), run a script (a lesson, the browser tests) and tell how it went (0
// none, 1 running, 2 succeeded, 3 failed, 4 a lesson waiting at a picture). main.cpp sets them; only the browser calls them.
struct Page_commands {
  std::function<void(const std::string& path)> open_file;
  std::function<void(const std::string& script)> run_script;
  std::function<int()> script_state;
};
void set_page_commands(Page_commands commands);
// The address the viewer was opened at, without its query ("" on the desktop): a link to what
// is shown is this and a query (viewer/link.hpp).
std::string page_address();

}  // namespace sculpt::viewer::platform
