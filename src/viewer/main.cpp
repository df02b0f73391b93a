// sculpt-view: the workbench window. GLFW + Dear ImGui 1.86 + the shared OpenGL 3.3 renderer.
// Our GL header first: it must be the first to include GL/gl.h (see render/gl.hpp).
#include "render/gl.hpp"
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
// clang-format on

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>

#include "figures/paper_figures.hpp"
#include "frontend/command_line.hpp"
#include "io/atomic_file.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"
#include "script.hpp"
#include "viewer.hpp"

namespace {

std::string glfw_error;

void on_glfw_error(int code, const char* description) {
  glfw_error = std::to_string(code) + ": " + description;
}

void on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* viewer = static_cast<sculpt::viewer::Viewer*>(glfwGetWindowUserPointer(window));
  if (count > 0 && viewer && !viewer->busy()) viewer->open_file(paths[0]);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sculpt-view: step through the sculpting reconstruction, in 2D and 3D"};
  std::string file, example = "star", script_path, screenshot;
  int frames = 0;
  std::string size = "1280x720";  // fits a 1366x768 laptop screen, title bar and task bar included
  float font_scale = 1.0f;
  bool bordered = false, closed = false, merge_duplicates = false;
  app.add_option("file", file, "Point file to open (default: the built-in example)");
  app.add_option("--example", example, "Built-in example to open")->capture_default_str();
  app.add_flag("--bordered", bordered,
               "Reconstruct a bordered surface (an example is reconstructed as its own kind "
               "otherwise, and a file as its samples show)");
  app.add_flag("--closed", closed, "Reconstruct a closed surface, also from a bordered example")
      ->excludes("--bordered");
  app.add_flag("--merge-duplicates", merge_duplicates,
               "Drop a file's repeated points instead of refusing the file");
  std::string method = sculpt::to_string(sculpt::Options{}.method);
  app.add_option("--method", method, sculpt::frontend::methods_help())
      ->capture_default_str()
      ->check(CLI::IsMember(sculpt::method_names()));
  std::string figure, panel;
  bool no_animation = false;
  app.add_option("--figure", figure,
                 "Open a figure of the paper (fig01 ... fig15) and tour it panel by panel")
      ->check([](const std::string& id) {
        return sculpt::figures::find_figure(id) ? std::string()
                                                : "no figure '" + id + "' (fig01 ... fig15)";
      });
  app.add_option("--panel", panel, "With --figure: start at this panel (a, b, ... or 1, 2, ...)")
      ->needs("--figure");
  app.add_flag("--no-animation", no_animation,
               "Jump to tour panels instead of moving the stage and camera there");
  auto* script_option =
      app.add_option("--script", script_path, "Run the commands of a script file, then quit");
  auto* frames_option = app.add_option("--frames", frames, "Draw this many frames, then quit")
                            ->check(CLI::PositiveNumber)
                            ->excludes(script_option);
  app.add_option("--screenshot", screenshot,
                 "With --frames: save the window to this PNG at the end")
      ->needs(frames_option);
  app.add_option("--size", size, "Window size WIDTHxHEIGHT")
      ->capture_default_str()
      ->check([](const std::string& text) {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) == 3 && x == 'x' &&
                       w >= 320 && h >= 240 && w <= 16384 && h <= 16384
                   ? std::string()
                   : "'" + text + "' is not WIDTHxHEIGHT from 320x240";
      });
  app.add_option("--font-scale", font_scale,
                 "Scale the panel's text, e.g. 1.5 for a projector (also in the View menu)")
      ->capture_default_str()
      ->check(CLI::Range(0.5f, 4.0f));
  app.footer(sculpt::frontend::exit_codes_help);
  if (const auto stop = sculpt::frontend::parse_command_line(app, argc, argv, "sculpt-view")) {
    return *stop;
  }

  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    std::cerr << "sculpt-view: no display to open a window on (" << glfw_error
              << "). Render pictures headless instead, e.g.\n"
                 "  sculpt render --example star --stage poles -o poles.png\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  int width = 0, height = 0;
  std::sscanf(size.c_str(), "%dx%d", &width, &height);
  GLFWwindow* window = glfwCreateWindow(width, height, "Sculpt", nullptr, nullptr);
  if (!window) {
    std::cerr << "sculpt-view: cannot open an OpenGL 3.3 window (" << glfw_error
              << "). Render pictures headless instead: sculpt render --help\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::GetIO().FontGlobalScale = font_scale;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = 0;
  {
    sculpt::viewer::Viewer viewer;
    glfwSetWindowUserPointer(window, &viewer);
    glfwSetDropCallback(window, on_drop);

    std::optional<sculpt::viewer::Script> script;
    try {
      if (!script_path.empty()) script = sculpt::viewer::Script::from_file(script_path);
      if (frames > 0) {
        script = sculpt::viewer::Script::from_text(
            "wait\nframes " + std::to_string(frames) +
            (screenshot.empty() ? "" : "\nscreenshot " + screenshot) + "\nquit\n");
      }
    } catch (const std::exception& e) {
      std::cerr << "sculpt-view: " << e.what() << '\n';
      return 1;
    }
    sculpt::Method chosen = sculpt::Options{}.method;
    sculpt::parse_method(method, chosen);
    viewer.set_method(chosen);
    viewer.set_animation(!no_animation);
    if (!figure.empty()) {
      viewer.open_figure(figure);
      if (!panel.empty() && !viewer.go_to_panel(panel)) {
        std::cerr << "sculpt-view: " << viewer.message() << '\n';
        return 2;
      }
    } else if (!file.empty()) {
      if (bordered || closed) {
        viewer.set_file_kind(bordered ? sculpt::Surface_kind::bordered
                                      : sculpt::Surface_kind::closed);
      }
      viewer.set_merge_duplicates(merge_duplicates);
      viewer.open_file(file);
    } else {
      viewer.open_example(example, bordered ? sculpt::Surface_kind::bordered
                                   : closed ? sculpt::Surface_kind::closed
                                            : sculpt::Surface_kind::automatic);
    }

    double last = glfwGetTime();
    while (!glfwWindowShouldClose(window) && !viewer.wants_to_quit()) {
      if (script || viewer.animating()) {
        glfwPollEvents();
      } else {
        glfwWaitEventsTimeout(0.1);
      }
      std::string screenshot_now;
      if (script) {
        screenshot_now = script->before_frame(viewer);
        if (script->finished() && screenshot_now.empty()) break;
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      const double now = glfwGetTime();
      viewer.frame(w, h, now - last);
      last = now;
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (!screenshot_now.empty()) {
        try {
          sculpt::render::write_png(screenshot_now, sculpt::render::read_pixels(w, h));
        } catch (const std::exception& e) {
          std::cerr << "sculpt-view: " << e.what() << '\n';
          status = 1;
        }
      }
      glfwSwapBuffers(window);
    }
    if (script && script->failed()) status = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
