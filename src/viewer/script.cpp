// SPDX-License-Identifier: GPL-3.0-or-later
#include "script.hpp"

#include "figures/paper_figures.hpp"
#include "frontend/closest_name.hpp"
#include "io/point_reader.hpp"
#include "scene/colours.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
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

// A whole word as a number in [low, high], or nothing.
std::optional<long> number(const std::string& word, long low, long high) {
  long value = 0;
  const char* end = word.data() + word.size();
  const auto [stop, error] = std::from_chars(word.data(), end, value);
  if (word.empty() || error != std::errc() || stop != end || value < low || value > high) {
    return std::nullopt;
  }
  return value;
}

// A picture size WIDTHxHEIGHT, 16 to 8192 pixels each, or nothing.
std::optional<std::pair<int, int>> picture_size(const std::string& word) {
  const auto x = word.find('x');
  if (x == std::string::npos) return std::nullopt;
  const auto width = number(word.substr(0, x), 16, 8192);
  const auto height = number(word.substr(x + 1), 16, 8192);
  if (!width || !height) return std::nullopt;
  return std::pair<int, int>(int(*width), int(*height));
}

// A whole word as a finite real number, or nothing.
std::optional<double> real(const std::string& word) {
  if (word.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Commands that take more than one argument parse their own.
bool takes_arguments(const std::string& command) {
  for (const char* name : {"export", "export-animation", "clip", "section", "add-point",
                           "move-point", "stroke", "layer", "camera", "replay"}) {
    if (command == name) return true;
  }
  return false;
}

}  // namespace

void Script::fail(const std::string& why) {
  // A script the options made (--frames) is not the user's: its failures are the run's.
  std::cerr << (from_options_ ? "sculpt-view: " : "sculpt-view: script: ") << why << '\n';
  failed_ = true;
}

Script Script::from_options(const std::string& text) {
  Script script = from_text(text);
  script.from_options_ = true;
  return script;
}

Script Script::from_file(const std::string& path) {
  // A script is a short text: a folder, a binary file or an endless device is refused at once,
  // not read until memory runs out or taken for an empty script.
  constexpr std::size_t longest_script = 1 << 20;
  if (std::filesystem::is_directory(path))
    throw std::runtime_error("the script '" + path + "' is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the script '" + path + "'");
  std::string text(longest_script + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw std::runtime_error("cannot read the script '" + path + "'");
  if (text.size() > longest_script)
    throw std::runtime_error("the script '" + path + "' is longer than 1 MiB: not a script");
  if (text.find('\0') != std::string::npos)
    throw std::runtime_error("the script '" + path + "' is binary, not text");
  return from_text(text);
}

Script Script::from_text(const std::string& text, Mode mode) {
  Script script;
  script.mode_ = mode;
  std::istringstream lines(text);
  std::string line, narration;
  while (std::getline(lines, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) {
      narration.clear();  // a blank line: the comments above narrate nothing
      continue;
    }
    if (line[first] == '#') {
      // A comment block right above a command narrates it (a lesson shows it).
      std::string words = line.substr(line.find_first_not_of("# \t", first) == std::string::npos
                                          ? line.size()
                                          : line.find_first_not_of("# \t", first));
      while (!words.empty() && (words.back() == ' ' || words.back() == '\r')) words.pop_back();
      if (words.empty()) {
        if (!narration.empty()) narration += "\n\n";
      } else {
        if (!narration.empty() && narration.back() != '\n') narration += ' ';
        narration += words;
      }
      continue;
    }
    line = line.substr(0, line.find('#'));
    if (line.rfind("screenshot", line.find_first_not_of(" \t")) != std::string::npos)
      ++script.pauses_;
    script.commands_.push_back({line, narration});
    narration.clear();
  }
  return script;
}

void Script::run_first(const std::string& commands) {
  Script first = from_text(commands);
  commands_.insert(commands_.begin(), first.commands_.begin(), first.commands_.end());
}

void Script::resume() {
  if (!paused_) return;
  paused_ = false;
  ++step_;
}

std::string Script::before_frame(Viewer& viewer) {
  if (paused_) return "";
  if (frames_to_wait_ > 0) {
    --frames_to_wait_;
    return "";
  }
  while (!commands_.empty()) {
    std::istringstream words(commands_.front().line);
    std::string command, argument;
    words >> command >> argument;
    if (!commands_.front().narration.empty() && mode_ == Mode::lesson)
      narration_ = commands_.front().narration;
    if (command == "wait" || command == "wait-idle") {
      if (viewer.busy()) return "";  // ask again next frame
      commands_.pop_front();
      // The reconstruction asked for must have come: an older one still on screen is not it.
      if (command == "wait" && (!viewer.has_reconstruction() || viewer.last_job_failed())) {
        fail(from_options_ ? viewer.message() : "no reconstruction: " + viewer.message());
      }
      continue;
    }
    if (command == "wait-replay") {  // until the replay playing has reached its end
      if (viewer.replay_playing() && scene::replays(viewer.stage())) return "";
      commands_.pop_front();
      continue;
    }
    const std::string line = commands_.front().line;
    commands_.pop_front();
    if (mode_ == Mode::lesson) {
      // A lesson is watched: a picture it would take is a pause until the user goes on, and it
      // writes no files.
      if (command == "screenshot") {
        paused_ = true;
        return "";
      }
      if (command == "export" || command == "export-animation" || command == "save-points" ||
          command == "save-result")
        continue;
    }
    std::string extra;
    words >> extra;
    // Every word after the command, for those that take several.
    std::vector<std::string> arguments;
    {
      std::istringstream all(line);
      std::string word;
      all >> word;
      while (all >> word) arguments.push_back(word);
    }
    // Arguments read as real numbers from `first` on; nothing if one is not a number.
    const auto reals = [&](std::size_t first) -> std::optional<std::vector<double>> {
      std::vector<double> values;
      for (std::size_t i = first; i < arguments.size(); ++i) {
        const auto value = real(arguments[i]);
        if (!value) return std::nullopt;
        values.push_back(*value);
      }
      return values;
    };
    // Each command: what it needs, one line on stderr when that is not what it got.
    const auto needs_argument = [&](const char* what) {
      if (!argument.empty()) return true;
      fail("'" + command + "' needs " + what);
      return false;
    };
    const auto count = [&](const char* what, long low, long high) -> std::optional<long> {
      if (!needs_argument(what)) return std::nullopt;
      const auto value = number(argument, low, high);
      if (!value) fail("'" + line + "': expected " + what);
      return value;
    };
    const auto done = [&](bool succeeded) {
      if (!succeeded) fail("'" + line + "': " + viewer.message());
    };
    // A switch: `command on` or `command off`.
    const auto on_off = [&](const auto& set) {
      if (argument == "on" || argument == "off") {
        set(argument == "on");
      } else {
        fail("'" + line + "': expected " + command + " on or off");
      }
    };
    if (!extra.empty() && !takes_arguments(command)) {
      fail("'" + line + "': one argument expected");
      continue;
    }
    if (command == "help") {
      std::cout
          << "commands: example NAME, open FILE, method NAME, clean auto|jet|none, stage ID, next, "
             "previous, "
             "compare A,B[,C,D] | off, step K, replay STAGE [PACE], wait-replay, "
             "pick-sample K, pick-pole K, clip "
             "POS AZ EL [SLAB] | off, "
             "section POS AZ EL | off, "
             "neighbourhood on|off, polar-balls EVERY|off, follow on|off, layer ID on|off, "
             "present on|off, palette paper|colour-blind, picture-scale S, kind "
             "closed|bordered|automatic, "
             "camera fit|zoom F|orbit YAW PITCH|pan X Y|save F|load F, edit on|off, "
             "add-point X Y, move-point K X Y, delete-point K, stroke SPACING X Y X Y... "
             "(SPACING a share of the box diagonal), undo, "
             "save-points F, save-result F, link, message, figures, explain, stats, "
             "figure ID, panel ID, "
             "expect-panel ID, key K, "
             "animation on|off, wait, wait-idle, expect-busy, expect-idle, cancel, frames N, "
             "screenshot F.png, export F.png [WxH], export-animation F.webp|F.gif [WxH [FRAMES]], "
             "quit\n";
    } else if (command == "kind") {
      Surface_kind kind;
      if (!needs_argument("closed, bordered or automatic")) continue;
      if (!parse_kind(argument, kind)) {
        fail("no kind '" + argument + "' (closed, bordered or automatic)");
        continue;
      }
      viewer.set_file_kind(kind);
    } else if (command == "example") {
      if (needs_argument("an example name")) viewer.open_example(argument, viewer.file_kind());
    } else if (command == "open") {
      if (needs_argument("a file")) viewer.open_file(argument);
    } else if (command == "stage") {
      scene::Stage stage;
      if (!needs_argument("a stage")) continue;
      if (!scene::parse_stage(argument, stage)) {
        std::vector<std::string> names;
        std::string listed;
        for (const scene::Stage known : scene::all_stages()) {
          names.emplace_back(scene::stage_id(known));
          listed += (listed.empty() ? "" : ", ") + names.back();
        }
        fail("no stage '" + argument + "'" + frontend::did_you_mean(argument, names) +
             "; the stages are " + listed);
        continue;
      }
      done(viewer.set_stage(stage));
    } else if (command == "next") {
      viewer.step_stage(+1);
    } else if (command == "previous") {
      viewer.step_stage(-1);
    } else if (command == "replay") {
      scene::Stage stage;
      double pace = 0;  // optional: steps a second
      std::istringstream pace_word(extra);
      const bool paced = !extra.empty();
      if (paced && !(pace_word >> pace)) pace = -1;
      std::string more;
      if (words >> more || !scene::parse_stage(argument, stage) || !scene::replays(stage) ||
          (paced && !(pace >= 1 && pace <= 2000))) {
        fail("'" + line +
             "': expected replay propagation (the labelling), carving, candidates (the "
             "pruning), front (the Advancing Front) or alpha (alpha shapes), then optionally "
             "the steps a second (1 to 2000)");
        continue;
      }
      done(viewer.start_replay(stage, float(pace)));
    } else if (command == "compare") {
      // compare a,b[,c,d]: methods side by side; compare off
      if (argument == "off") {
        viewer.stop_compare();
        continue;
      }
      std::vector<Method> methods;
      std::string name, unknown;
      std::istringstream names(argument);
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
        fail("'" + line + "': no method '" + unknown + "'" +
             frontend::did_you_mean(unknown, known));
        continue;
      }
      if (methods.size() < 2 || methods.size() > 4) {
        fail("'" + line + "': expected compare A,B[,C,D] (two to four methods) or compare off");
        continue;
      }
      done(viewer.start_compare(methods));
    } else if (command == "step") {
      if (viewer.has_reconstruction() && !viewer.has_replay()) {
        fail("'" + line +
             "': this method has no replay (of the labelling, the carving or the "
             "pruning)");
        continue;
      }
      viewer.pause_replay();  // a step chosen by hand stays on screen
      if (const auto events = count("a number of events (or -1 for all)", -1, 1L << 30)) {
        viewer.set_step(*events);
      }
    } else if (command == "clip") {
      // clip POSITION AZIMUTH ELEVATION, or clip off
      if (viewer.shown_dimension() == 2) {
        fail("'" + line + "': the clip cuts 3D stages; this is a curve");
      } else if (argument == "off") {
        viewer.clear_clip();
      } else {
        scene::Clip clip;
        std::istringstream numbers(argument + " " + extra);
        numbers >> clip.position >> clip.azimuth;
        if (numbers && (words >> clip.elevation) && clip.position >= 0 && clip.position <= 1) {
          if (!(words >> clip.slab)) clip.slab = 0;  // optional
          viewer.set_clip(clip);
        } else {
          fail("'" + line +
               "': expected clip POSITION AZIMUTH ELEVATION [SLAB] (position 0 to 1, angles "
               "in degrees, slab a share of the box) or clip off");
        }
      }
    } else if (command == "section") {
      // section POSITION AZIMUTH ELEVATION, or section off
      if (viewer.shown_dimension() == 2) {
        fail("'" + line + "': a section cuts 3D stages; this is a curve");
      } else if (argument == "off") {
        viewer.clear_section();
      } else {
        scene::Clip plane;
        std::istringstream numbers(argument + " " + extra);
        numbers >> plane.position >> plane.azimuth;
        std::string more;
        if (numbers && (words >> plane.elevation) && !(words >> more) && plane.position >= 0 &&
            plane.position <= 1 && std::isfinite(plane.azimuth) && std::isfinite(plane.elevation)) {
          viewer.set_section(plane);
        } else {
          fail("'" + line +
               "': expected section POSITION AZIMUTH ELEVATION (position 0 to 1 across the "
               "box, the plane's normal in degrees) or section off");
        }
      }
    } else if (command == "pick-sample") {
      if (const auto sample =
              count("a sample index (or -1)", -1, long(std::numeric_limits<int>::max()))) {
        done(viewer.pick_sample(int(*sample)));
      }
    } else if (command == "pick-pole") {
      if (const auto pole =
              count("a pole index (or -1)", -1, long(std::numeric_limits<int>::max()))) {
        done(viewer.pick_pole(int(*pole)));
      }
    } else if (command == "method") {
      if (needs_argument("a method name")) done(viewer.switch_method(argument));
    } else if (command == "clean") {
      if (needs_argument("auto, jet or none")) done(viewer.switch_cleaning(argument));
    } else if (command == "figure") {
      if (needs_argument("a figure (fig01 ... fig15)")) done(viewer.open_figure(argument));
    } else if (command == "panel") {
      if (needs_argument("next, previous, a number or a letter")) {
        done(viewer.go_to_panel(argument));
      }
    } else if (command == "expect-panel") {
      if (viewer.panel_on_screen() != argument) {
        fail("expected panel " + (argument.empty() ? "none" : argument) + " on screen, not '" +
             viewer.panel_on_screen() + "' (" + viewer.message() + ")");
      }
    } else if (command == "key") {
      if (!needs_argument("a key name")) continue;
      const int key = key_code(argument);
      if (key < 0) {
        fail("no key '" + argument + "'");
      } else {
        viewer.press_key(key);
      }
    } else if (command == "animation") {
      on_off([&](bool on) { viewer.set_animation(on); });
    } else if (command == "frames") {
      if (const auto frames = count("a number of frames (1 to 100000)", 1, 100000)) {
        frames_to_wait_ = int(*frames) - 1;
        return "";
      }
    } else if (command == "screenshot") {
      if (!needs_argument("a PNG path")) continue;
      // Written as the extension says, or refused: never PNG bytes under another name.
      if (io::extension_of(argument) != ".png") {
        fail("'" + line + "': a screenshot is a PNG image: the path must end in .png");
        continue;
      }
      return argument;
    } else if (command == "export") {
      if (!needs_argument("a PNG path")) continue;
      const auto size = extra.empty() ? std::pair<int, int>(800, 600) : picture_size(extra);
      if (!size) {
        fail("'" + line + "': expected a size WIDTHxHEIGHT, 16 to 8192 pixels each");
        continue;
      }
      done(viewer.export_picture(argument, size->first, size->second));
    } else if (command == "message") {
      // The panel's message line (what was opened, saved or refused), on standard output.
      std::cout << "message: " << viewer.message() << std::endl;
    } else if (command == "figures") {
      // The paper's figures and their panels, one JSON line on standard output.
      nlohmann::json all = nlohmann::json::array();
      for (const auto& figure : figures::paper_figures()) {
        nlohmann::json panels = nlohmann::json::array();
        for (std::size_t i = 0; i < figure.images.size(); ++i)
          panels.push_back(figure.id + figure.images[i].suffix);
        all.push_back({{"id", figure.id}, {"panels", panels}});
      }
      std::cout << "figures: " << all.dump() << std::endl;
    } else if (command == "explain") {
      // The Explanation panel's paragraph, on standard output: for demos and tests.
      if (!viewer.has_reconstruction()) {
        fail("'explain': no reconstruction on screen");
        continue;
      }
      std::cout << "explain " << scene::stage_id(viewer.stage()) << ": " << viewer.explanation()
                << std::endl;
    } else if (command == "camera") {
      // camera fit | zoom F | orbit YAW PITCH | pan RIGHT UP | save FILE | load FILE
      const auto values = reals(1);
      const std::size_t count = values ? values->size() : 0;
      const std::string what = arguments.empty() ? "" : arguments[0];
      if (what == "fit" && arguments.size() == 1) {
        viewer.reset_camera();
      } else if (what == "zoom" && count == 1 && (*values)[0] >= 1e-3 && (*values)[0] <= 1e3) {
        viewer.zoom_camera(float((*values)[0]));
      } else if (what == "orbit" && count == 2 && std::abs((*values)[0]) <= 3600 &&
                 std::abs((*values)[1]) <= 3600) {
        viewer.orbit_camera(float((*values)[0]), float((*values)[1]));
      } else if (what == "pan" && count == 2 && std::abs((*values)[0]) <= 1e3 &&
                 std::abs((*values)[1]) <= 1e3) {
        viewer.pan_camera(float((*values)[0]), float((*values)[1]));
      } else if ((what == "save" || what == "load") && arguments.size() == 2) {
        done(what == "save" ? viewer.save_camera(arguments[1]) : viewer.load_camera(arguments[1]));
      } else {
        fail("'" + line +
             "': expected camera fit, zoom FACTOR, orbit YAW PITCH (degrees), pan RIGHT UP "
             "(half heights), save FILE or load FILE");
      }
    } else if (command == "export-animation") {
      // export-animation PATH.webp|PATH.gif [WIDTHxHEIGHT [FRAMES]]
      if (arguments.empty()) {
        fail("'export-animation' needs a .webp or .gif path");
        continue;
      }
      const auto size =
          arguments.size() > 1 ? picture_size(arguments[1]) : std::pair<int, int>(800, 600);
      const auto frames = arguments.size() > 2 ? number(arguments[2], 2, 2000) : 60L;
      if (!size || !frames || arguments.size() > 3) {
        fail("'" + line +
             "': expected export-animation PATH.webp|PATH.gif [WIDTHxHEIGHT [FRAMES 2-2000]]");
        continue;
      }
      done(viewer.export_animation(arguments[0], size->first, size->second, int(*frames)));
    } else if (command == "neighbourhood") {
      on_off([&](bool on) {
        if (on && viewer.picked_sample() < 0) {
          fail("'" + line + "': pick a sample first (pick-sample K)");
          return;
        }
        viewer.set_neighbourhood(on);
      });
    } else if (command == "polar-balls") {
      // polar-balls EVERY (every k-th pole's ball; 0 or off: none)
      const auto every = argument == "off" ? std::optional<long>(0) : number(argument, 0, 1000000);
      if (every) {
        viewer.show_polar_balls(int(*every));
      } else {
        fail("'" + line + "': expected polar-balls EVERY (1 for all, 0 or off for none)");
      }
    } else if (command == "follow") {
      on_off([&](bool on) { viewer.set_follow(on); });
    } else if (command == "palette") {
      scene::Colours colours;
      if (scene::parse_colours(argument, colours)) {
        viewer.set_colour_blind(colours == scene::Colours::colour_blind);
      } else {
        fail("'" + line + "': expected palette paper or palette colour-blind");
      }
    } else if (command == "present") {
      on_off([&](bool on) { viewer.set_presenting(on); });
    } else if (command == "picture-scale") {
      const auto scale = real(argument);
      if (!scale || *scale < Viewer::smallest_picture_scale ||
          *scale > Viewer::largest_picture_scale) {
        fail("'" + line + "': expected a picture scale from 0.5 to 4");
        continue;
      }
      viewer.set_picture_scale(float(*scale));
    } else if (command == "edit") {
      on_off([&](bool on) {
        if (on && viewer.shown_dimension() == 3) {
          fail("'" + line + "': samples are edited in 2D; this is a surface");
          return;
        }
        viewer.set_editing(on);
      });
    } else if (command == "add-point") {
      const auto xy = reals(0);
      if (!xy || xy->size() != 2) {
        fail("'" + line + "': expected add-point X Y");
        continue;
      }
      done(viewer.add_point({(*xy)[0], (*xy)[1]}));
    } else if (command == "move-point") {
      const auto sample = arguments.empty()
                              ? std::nullopt
                              : number(arguments[0], 0, long(std::numeric_limits<int>::max()));
      const auto xy = reals(1);
      if (!sample || !xy || xy->size() != 2) {
        fail("'" + line + "': expected move-point SAMPLE X Y");
        continue;
      }
      done(viewer.move_point(int(*sample), {(*xy)[0], (*xy)[1]}));
    } else if (command == "delete-point") {
      if (const auto sample = count("a sample index", 0, long(std::numeric_limits<int>::max()))) {
        done(viewer.delete_point(int(*sample)));
      }
    } else if (command == "stroke") {
      // stroke SPACING X1 Y1 X2 Y2 ...: a drawn polyline resampled SPACING apart (a share of
      // the samples' box diagonal).
      const auto values = reals(0);
      if (!values || values->size() < 5 || values->size() % 2 != 1 || (*values)[0] < 0.001 ||
          (*values)[0] > 1) {
        fail("'" + line +
             "': expected stroke SPACING X1 Y1 X2 Y2 ... (spacing 0.001 to 1, a share of "
             "the samples' box diagonal)");
        continue;
      }
      std::vector<Point<2>> stroke;
      for (std::size_t i = 1; i + 1 < values->size(); i += 2)
        stroke.push_back({(*values)[i], (*values)[i + 1]});
      done(viewer.add_stroke(stroke, (*values)[0]));
    } else if (command == "undo") {
      done(viewer.undo_edit());
    } else if (command == "save-points") {
      if (needs_argument("a .xy path")) done(viewer.save_points(argument));
    } else if (command == "save-result") {
      if (needs_argument("a path (.ply .obj .stl .off, or .svg .obj for a curve)"))
        done(viewer.save_result(argument));
    } else if (command == "link") {
      // The link (browser) or command line (desktop) that opens this view, on standard output.
      std::string why_not;
      const std::string link = viewer.link_to_view(why_not);
      if (link.empty()) {
        fail("'link': no link to this view: " + why_not);
        continue;
      }
      std::cout << "link: " << link << std::endl;
    } else if (command == "layer") {
      if (arguments.size() != 2 || (arguments[1] != "on" && arguments[1] != "off")) {
        fail("'" + line + "': expected layer NAME on|off");
        continue;
      }
      done(viewer.set_layer_visible(arguments[0], arguments[1] == "on"));
    } else if (command == "stats") {
      // The shown reconstruction's statistics, one JSON line on standard output.
      if (!viewer.has_reconstruction()) {
        fail("'stats': no reconstruction on screen");
        continue;
      }
      std::cout << "stats: " << viewer.statistics_line() << std::endl;
    } else if (command == "cancel") {
      viewer.cancel();
    } else if (command == "expect-busy") {
      if (!viewer.busy()) fail("expected a reconstruction to be running");
    } else if (command == "expect-idle") {
      // No reconstruction runs (right after `cancel`: a cancel takes effect at once).
      if (viewer.reconstructing()) fail("expected no reconstruction to be running");
    } else if (command == "quit") {
      commands_.clear();
      return "";
    } else {
      fail("unknown command '" + command + "' (`help` lists them)");
    }
  }
  return "";
}

}  // namespace sculpt::viewer
