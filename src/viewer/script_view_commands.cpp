// SPDX-License-Identifier: GPL-3.0-or-later
// The script's commands that change what the viewer shows and how: what is opened, the stage,
// replays and comparisons, cuts, picks, the camera, the tour, keys and display switches.
#include "frontend/closest_name.hpp"
#include "scene/colours.hpp"
#include "script_line.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sculpt::viewer {
namespace {

// The keys a script can press, by the names the viewer's help uses.
int key_code(const std::string& name) {
  static const std::map<std::string, int> keys = {{"pagedown", GLFW_KEY_PAGE_DOWN},
                                                  {"pageup", GLFW_KEY_PAGE_UP},
                                                  {"]", GLFW_KEY_RIGHT_BRACKET},
                                                  {"[", GLFW_KEY_LEFT_BRACKET},
                                                  {"t", GLFW_KEY_T},
                                                  {"escape", GLFW_KEY_ESCAPE},
                                                  {"right", GLFW_KEY_RIGHT},
                                                  {"left", GLFW_KEY_LEFT},
                                                  {"space", GLFW_KEY_SPACE},
                                                  {".", GLFW_KEY_PERIOD},
                                                  {",", GLFW_KEY_COMMA},
                                                  {"r", GLFW_KEY_R},
                                                  {"h", GLFW_KEY_H},
                                                  {"f5", GLFW_KEY_F5}};
  const auto found = keys.find(name);
  return found == keys.end() ? -1 : found->second;
}

// A plane as clip and section take it, POSITION AZIMUTH ELEVATION: whether the three were read,
// the position 0 to 1 across the box and the normal's angles finite.
bool read_plane(Script_line& line, scene::Clip& plane) {
  std::istringstream numbers(line.argument + " " + line.extra);
  numbers >> plane.position >> plane.azimuth;
  return numbers && (line.words >> plane.elevation) && plane.position >= 0 && plane.position <= 1 &&
         std::isfinite(plane.azimuth) && std::isfinite(plane.elevation);
}

}  // namespace

bool run_view_command(Script_line& line) {
  Viewer& viewer = line.viewer;
  if (line.command == "kind") {
    Surface_kind kind;
    if (!line.needs_argument("closed, bordered or automatic")) return true;
    if (!parse_kind(line.argument, kind)) {
      line.fail("no kind '" + line.argument + "' (closed, bordered or automatic)");
      return true;
    }
    viewer.set_file_kind(kind);
  } else if (line.command == "example") {
    if (line.needs_argument("an example name"))
      viewer.open_example(line.argument, viewer.file_kind());
  } else if (line.command == "open") {
    if (line.needs_argument("a file")) viewer.open_file(line.argument);
  } else if (line.command == "stage") {
    scene::Stage stage;
    if (!line.needs_argument("a stage")) return true;
    if (!scene::parse_stage(line.argument, stage)) {
      std::vector<std::string> names;
      std::string listed;
      for (const scene::Stage known : scene::all_stages()) {
        names.emplace_back(scene::stage_id(known));
        listed += (listed.empty() ? "" : ", ") + names.back();
      }
      line.fail("no stage '" + line.argument + "'" + frontend::did_you_mean(line.argument, names) +
                "; the stages are " + listed);
      return true;
    }
    line.done(viewer.set_stage(stage));
  } else if (line.command == "next") {
    viewer.step_stage(+1);
  } else if (line.command == "previous") {
    viewer.step_stage(-1);
  } else if (line.command == "replay") {
    scene::Stage stage;
    double pace = 0;  // optional: steps a second
    std::istringstream pace_word(line.extra);
    const bool paced = !line.extra.empty();
    if (paced && !(pace_word >> pace)) pace = -1;
    std::string more;
    if (line.words >> more || !scene::parse_stage(line.argument, stage) || !scene::replays(stage) ||
        (paced && !(pace >= 1 && pace <= 2000))) {
      line.fail("'" + line.text +
                "': expected replay propagation (the labelling), carving, candidates (the "
                "pruning), front (the Advancing Front) or alpha (alpha shapes), then optionally "
                "the steps a second (1 to 2000)");
      return true;
    }
    line.done(viewer.start_replay(stage, float(pace)));
  } else if (line.command == "compare") {
    // compare a,b[,c,d]: methods side by side; compare off
    if (line.argument == "off") {
      viewer.stop_compare();
      return true;
    }
    std::vector<Method> methods;
    std::string name, unknown;
    std::istringstream names(line.argument);
    while (std::getline(names, name, ',')) {
      Method method;
      if (parse_method(name, method)) {
        methods.push_back(method);
      } else if (unknown.empty()) {
        unknown = name;
      }
    }
    if (!unknown.empty()) {
      std::vector<std::string> known;
      for (const char* n : method_names()) known.emplace_back(n);
      line.fail("'" + line.text + "': no method '" + unknown + "'" +
                frontend::did_you_mean(unknown, known));
      return true;
    }
    if (methods.size() < 2 || methods.size() > 4) {
      line.fail("'" + line.text +
                "': expected compare A,B[,C,D] (two to four methods) or compare off");
      return true;
    }
    line.done(viewer.start_compare(methods));
  } else if (line.command == "step") {
    if (viewer.has_reconstruction() && !viewer.has_replay()) {
      line.fail("'" + line.text +
                "': this method has no replay (of the labelling, the carving or the "
                "pruning)");
      return true;
    }
    viewer.pause_replay();  // a step chosen by hand stays on screen
    if (const auto events = line.count("a number of events (or -1 for all)", -1, 1L << 30)) {
      viewer.set_step(*events);
    }
  } else if (line.command == "clip") {
    // clip POSITION AZIMUTH ELEVATION, or clip off
    if (viewer.shown_dimension() == 2) {
      line.fail("'" + line.text + "': the clip cuts 3D stages; this is a curve");
    } else if (line.argument == "off") {
      viewer.clear_clip();
    } else {
      scene::Clip clip;
      if (read_plane(line, clip)) {
        if (!(line.words >> clip.slab)) clip.slab = 0;  // optional
        viewer.set_clip(clip);
      } else {
        line.fail("'" + line.text +
                  "': expected clip POSITION AZIMUTH ELEVATION [SLAB] (position 0 to 1, angles "
                  "in degrees, slab a share of the box) or clip off");
      }
    }
  } else if (line.command == "section") {
    // section POSITION AZIMUTH ELEVATION, or section off
    if (viewer.shown_dimension() == 2) {
      line.fail("'" + line.text + "': a section cuts 3D stages; this is a curve");
    } else if (line.argument == "off") {
      viewer.clear_section();
    } else {
      scene::Clip plane;
      std::string more;
      if (read_plane(line, plane) && !(line.words >> more)) {
        viewer.set_section(plane);
      } else {
        line.fail("'" + line.text +
                  "': expected section POSITION AZIMUTH ELEVATION (position 0 to 1 across the "
                  "box, the plane's normal in degrees) or section off");
      }
    }
  } else if (line.command == "pick-sample") {
    if (const auto sample =
            line.count("a sample index (or -1)", -1, long(std::numeric_limits<int>::max()))) {
      line.done(viewer.pick_sample(int(*sample)));
    }
  } else if (line.command == "pick-pole") {
    if (const auto pole =
            line.count("a pole index (or -1)", -1, long(std::numeric_limits<int>::max()))) {
      line.done(viewer.pick_pole(int(*pole)));
    }
  } else if (line.command == "method") {
    if (line.needs_argument("a method name")) line.done(viewer.switch_method(line.argument));
  } else if (line.command == "clean") {
    if (line.needs_argument(cleaning_choices())) line.done(viewer.switch_cleaning(line.argument));
  } else if (line.command == "figure") {
    if (line.needs_argument("a figure (fig01 ... fig15)"))
      line.done(viewer.open_figure(line.argument));
  } else if (line.command == "panel") {
    if (line.needs_argument("next, previous, a number or a letter")) {
      line.done(viewer.go_to_panel(line.argument));
    }
  } else if (line.command == "expect-panel") {
    if (viewer.panel_on_screen() != line.argument) {
      line.fail("expected panel " + (line.argument.empty() ? "none" : line.argument) +
                " on screen, not '" + viewer.panel_on_screen() + "' (" + viewer.message() + ")");
    }
  } else if (line.command == "key") {
    if (!line.needs_argument("a key name")) return true;
    const int key = key_code(line.argument);
    if (key < 0) {
      line.fail("no key '" + line.argument + "'");
    } else {
      viewer.press_key(key);
    }
  } else if (line.command == "animation") {
    line.on_off([&](bool on) { viewer.set_animation(on); });
  } else if (line.command == "camera") {
    // camera fit | zoom F | orbit YAW PITCH | pan RIGHT UP | save FILE | load FILE
    const auto values = line.reals(1);
    const std::size_t count = values ? values->size() : 0;
    const std::string what = line.arguments.empty() ? "" : line.arguments[0];
    if (what == "fit" && line.arguments.size() == 1) {
      viewer.reset_camera();
    } else if (what == "zoom" && count == 1 && (*values)[0] >= 1e-3 && (*values)[0] <= 1e3) {
      viewer.zoom_camera(float((*values)[0]));
    } else if (what == "orbit" && count == 2 && std::abs((*values)[0]) <= 3600 &&
               std::abs((*values)[1]) <= 3600) {
      viewer.orbit_camera(float((*values)[0]), float((*values)[1]));
    } else if (what == "pan" && count == 2 && std::abs((*values)[0]) <= 1e3 &&
               std::abs((*values)[1]) <= 1e3) {
      viewer.pan_camera(float((*values)[0]), float((*values)[1]));
    } else if ((what == "save" || what == "load") && line.arguments.size() == 2) {
      line.done(what == "save" ? viewer.save_camera(line.arguments[1])
                               : viewer.load_camera(line.arguments[1]));
    } else {
      line.fail("'" + line.text +
                "': expected camera fit, zoom FACTOR, orbit YAW PITCH (degrees), pan RIGHT UP "
                "(half heights), save FILE or load FILE");
    }
  } else if (line.command == "neighbourhood") {
    line.on_off([&](bool on) {
      if (on && viewer.picked_sample() < 0) {
        line.fail("'" + line.text + "': pick a sample first (pick-sample K)");
        return;
      }
      viewer.set_neighbourhood(on);
    });
  } else if (line.command == "polar-balls") {
    // polar-balls EVERY (every k-th pole's ball; 0 or off: none)
    const auto every =
        line.argument == "off" ? std::optional<long>(0) : number(line.argument, 0, 1000000);
    if (every) {
      viewer.show_polar_balls(int(*every));
    } else {
      line.fail("'" + line.text + "': expected polar-balls EVERY (1 for all, 0 or off for none)");
    }
  } else if (line.command == "follow") {
    line.on_off([&](bool on) { viewer.set_follow(on); });
  } else if (line.command == "palette") {
    scene::Colours colours;
    if (scene::parse_colours(line.argument, colours)) {
      viewer.set_colour_blind(colours == scene::Colours::colour_blind);
    } else {
      line.fail("'" + line.text + "': expected palette paper or palette colour-blind");
    }
  } else if (line.command == "present") {
    line.on_off([&](bool on) { viewer.set_presenting(on); });
  } else if (line.command == "picture-scale") {
    const auto scale = real(line.argument);
    if (!scale || *scale < Viewer::smallest_picture_scale ||
        *scale > Viewer::largest_picture_scale) {
      line.fail("'" + line.text + "': expected a picture scale from 0.5 to 4");
      return true;
    }
    viewer.set_picture_scale(float(*scale));
  } else if (line.command == "layer") {
    if (line.arguments.size() != 2 || (line.arguments[1] != "on" && line.arguments[1] != "off")) {
      line.fail("'" + line.text + "': expected layer NAME on|off");
      return true;
    }
    line.done(viewer.set_layer_visible(line.arguments[0], line.arguments[1] == "on"));
  } else {
    return false;
  }
  return true;
}

}  // namespace sculpt::viewer
