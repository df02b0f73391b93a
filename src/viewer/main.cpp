// SPDX-License-Identifier: GPL-3.0-or-later
// sculpt-view: the workbench window. GLFW + Dear ImGui 1.86 + the shared renderer, on the desktop
// (OpenGL 3.3) and in the browser (WebGL 2), where the page's address gives the options below.
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <optional>

#include "app.hpp"
#include "figures/paper_figures.hpp"
#include "frontend/command_line.hpp"
#include "io/temporary_files.hpp"
#include "lessons.hpp"
#include "platform/platform.hpp"
#include "scene/colours.hpp"
#include "scene/scene.hpp"

namespace {

std::string glfw_error;

void on_glfw_error(int code, const char* description) {
  glfw_error = std::to_string(code) + ": " + description;
}

}  // namespace

int main(int argc, char** argv) {
  // A save interrupted by a signal leaves no hidden temporary behind.
  sculpt::io::remove_temporaries_on_signals();
  CLI::App command_line{"sculpt-view: step through the sculpting reconstruction, in 2D and 3D"};
  std::string file, example = "star", script_path, screenshot;
  int frames = 0;
  std::string size = "1280x720";  // fits a 1366x768 laptop screen, title bar and task bar included
  float font_scale = 1.0f;
  bool bordered = false, closed = false, merge_duplicates = false;
  auto* file_option =
      command_line.add_option("file", file, "Point file to open (default: the built-in example)");
  command_line.add_option("--example", example, "Built-in example to open")
      ->capture_default_str()
      ->excludes(file_option);
  command_line.add_flag(
      "--bordered", bordered,
      "Reconstruct a bordered surface (an example is reconstructed as its own kind "
      "otherwise, and a file as its samples show)");
  command_line
      .add_flag("--closed", closed, "Reconstruct a closed surface, also from a bordered example")
      ->excludes("--bordered");
  command_line
      .add_flag("--merge-duplicates", merge_duplicates,
                "Drop a file's repeated points instead of refusing the file")
      ->needs(file_option);
  std::string method = sculpt::to_string(sculpt::Options{}.method);
  command_line.add_option("--method", method, sculpt::frontend::methods_help())
      ->capture_default_str()
      ->check(CLI::IsMember(sculpt::method_names()));
  std::string figure, panel;
  bool no_animation = false;
  command_line
      .add_option("--figure", figure,
                  "Open a figure of the paper (fig01 ... fig15) and tour it panel by panel")
      ->check([](const std::string& id) {
        return sculpt::figures::find_figure(id) ? std::string()
                                                : "no figure '" + id + "' (fig01 ... fig15)";
      })
      // A figure shows its own data, method and kind.
      ->excludes(file_option)
      ->excludes("--example")
      ->excludes("--method")
      ->excludes("--bordered")
      ->excludes("--closed");
  command_line
      .add_option("--panel", panel, "With --figure: start at this panel (a, b, ... or 1, 2, ...)")
      ->needs("--figure");
  command_line.add_flag("--no-animation", no_animation,
                        "Jump to tour panels instead of moving the stage and camera there");
  auto* script_option = command_line.add_option("--script", script_path,
                                                "Run the commands of a script file, then quit");
  auto* frames_option =
      command_line.add_option("--frames", frames, "Draw this many frames, then quit")
          ->check(CLI::PositiveNumber)
          ->excludes(script_option);
  command_line
      .add_option("--screenshot", screenshot,
                  "With --frames: save the window to this PNG at the end")
      ->needs(frames_option);
  command_line.add_option("--size", size, "Window size WIDTHxHEIGHT")
      ->capture_default_str()
      ->check([](const std::string& text) {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) == 3 && x == 'x' &&
                       w >= 320 && h >= 240 && w <= 16384 && h <= 16384
                   ? std::string()
                   : "'" + text + "' is not WIDTHxHEIGHT from 320x240";
      });
  command_line
      .add_option("--font-scale", font_scale,
                  "Scale the panel's text, e.g. 1.5 for a projector (also in the View menu)")
      ->capture_default_str()
      ->check(sculpt::frontend::scale_from(0.5, 4.0));
  bool present = false;
  float picture_scale = 1.0f;
  std::string palette = "paper";
  command_line
      .add_option("--palette", palette,
                  "Colours: paper or colour-blind (every pair of layers apart with "
                  "deuteranopia and protanopia too; also in the View menu)")
      ->capture_default_str()
      ->check([](const std::string& name) {
        sculpt::scene::Colours colours;
        return sculpt::scene::parse_colours(name, colours)
                   ? std::string()
                   : "no palette '" + name + "' (palettes: paper, colour-blind)";
      });
  command_line.add_flag("--present", present,
                        "Presentation mode: no panel, the legend in the picture (F5 toggles it)");
  command_line
      .add_option("--picture-scale", picture_scale,
                  "Scale the picture's points, lines and legend, e.g. 2 for a projector")
      ->capture_default_str()
      ->check(sculpt::frontend::scale_from(sculpt::viewer::Viewer::smallest_picture_scale,
                                           sculpt::viewer::Viewer::largest_picture_scale));
  // The first view: what a link to the viewer opens (in the browser, the page's address gives
  // these options: ?example=torus&method=paper&stage=poles).
  std::string stage;
  long step = -1;
  int picked_sample = -1;
  command_line.add_option("--stage", stage, "Show this stage once reconstructed (e.g. poles)")
      ->check([](const std::string& id) {
        sculpt::scene::Stage parsed;
        if (sculpt::scene::parse_stage(id, parsed)) return std::string();
        std::string stages;
        for (auto known : sculpt::scene::all_stages())
          stages += (stages.empty() ? "" : ", ") + std::string(sculpt::scene::stage_id(known));
        return "no stage '" + id + "' (stages: " + stages + ")";
      });
  command_line
      .add_option(
          "--step", step,
          "With --stage propagation, carving, candidates, front or alpha: the replay's events "
          "or steps shown")
      ->check(CLI::Range(0L, 1L << 30));
  command_line.add_option("--pick-sample", picked_sample, "Select this sample once reconstructed")
      ->check(CLI::NonNegativeNumber);
  std::string lesson;
  command_line
      .add_option(
          "--lesson", lesson,
          "Run a shipped lesson step by step (Next or Page Down goes on): " +
              [] {
                std::string names;
                for (const auto& l : sculpt::viewer::lessons())
                  names += std::string(names.empty() ? "" : ", ") + l.name;
                return names;
              }())
      ->check([](const std::string& name) {
        return sculpt::viewer::find_lesson(name) ? std::string() : "no lesson '" + name + "'";
      })
      ->excludes(script_option)
      ->excludes(frames_option)
      ->excludes("--stage")
      ->excludes("--step")
      ->excludes("--pick-sample")
      // A lesson opens its own examples (the method stays the user's).
      ->excludes(file_option)
      ->excludes("--example")
      ->excludes("--figure")
      ->excludes("--bordered")
      ->excludes("--closed");
  command_line.footer(
      "Exit codes: 0 success; 1 a file that cannot be read, a script that fails, a reconstruction "
      "that fails under --frames or a script's wait, a picture that cannot be written; 2 bad "
      "usage. Every failure is one line on stderr.");
  if (const auto stop =
          sculpt::frontend::parse_command_line(command_line, argc, argv, "sculpt-view")) {
    return *stop;
  }
  if (sculpt::scene::Stage replayed; step >= 0 && !(sculpt::scene::parse_stage(stage, replayed) &&
                                                    sculpt::scene::replays(replayed))) {
    std::cerr << "sculpt-view: usage error: --step chooses a moment of a replay, at --stage "
                 "propagation, carving, candidates, front or alpha"
              << (stage.empty() ? "" : "; this is the stage " + stage)
              << " (see sculpt-view --help)\n";
    return sculpt::frontend::exit_bad_usage;
  }

  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    std::cerr << "sculpt-view: no display to open a window on (" << glfw_error
              << "). Render pictures headless instead, e.g.\n"
                 "  sculpt render --example star --stage poles -o poles.png\n";
    return 1;
  }
  int width = 0, height = 0;
  std::sscanf(size.c_str(), "%dx%d", &width, &height);
  std::string why;
  GLFWwindow* window = sculpt::viewer::platform::open_window(width, height, why);
  if (!window) {
    std::cerr << "sculpt-view: " << why << " (" << glfw_error
              << "). Render pictures headless instead: sculpt render --help\n";
    glfwTerminate();
    return 1;
  }

  auto app = std::make_unique<sculpt::viewer::App>(window, font_scale);
  sculpt::viewer::Viewer& viewer = app->viewer();
  viewer.set_presenting(present);
  viewer.set_picture_scale(picture_scale);
  sculpt::scene::Colours colours = sculpt::scene::Colours::paper;
  sculpt::scene::parse_colours(palette, colours);
  viewer.set_colour_blind(colours == sculpt::scene::Colours::colour_blind);
  try {
    // The first view, before anything a script or --frames does with it.
    std::string first_view;
    if (!stage.empty()) first_view += "stage " + stage + "\n";
    if (step >= 0) first_view += "step " + std::to_string(step) + "\n";
    if (picked_sample >= 0) first_view += "pick-sample " + std::to_string(picked_sample) + "\n";
    if (!first_view.empty()) first_view = "wait\n" + first_view;
    std::optional<sculpt::viewer::Script> script;
    if (!script_path.empty()) script = sculpt::viewer::Script::from_file(script_path);
    if (frames > 0) {
      script = sculpt::viewer::Script::from_options(
          "wait\nframes " + std::to_string(frames) +
          (screenshot.empty() ? "" : "\nscreenshot " + screenshot) + "\nquit\n");
    }
    if (script) {
      script->run_first(first_view);
      app->run_script(std::move(*script), true);
    } else if (!first_view.empty()) {
      app->run_script(sculpt::viewer::Script::from_text(first_view), false);
    }
    if (!lesson.empty()) app->start_lesson(lesson);
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

  sculpt::viewer::platform::set_page_commands(
      {[viewer = &viewer](const std::string& path) {
         if (!viewer->busy()) viewer->open_file(path);
       },
       [app = app.get()](const std::string& text) {
         app->run_script(sculpt::viewer::Script::from_text(text), false);
       },
       [app = app.get()] { return int(app->script_state()); }});
  sculpt::viewer::platform::run_main_loop([app = app.get()] { return app->frame(); });
  if (sculpt::viewer::platform::in_browser) {
    app.release();  // the page calls its frames for as long as it is open
    return 0;
  }
  const int status = app->exit_status();
  app.reset();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
