#include "script.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

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
                                                  {"h", GLFW_KEY_H}};
  const auto found = keys.find(name);
  return found == keys.end() ? -1 : found->second;
}

}  // namespace

Script Script::from_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open the script '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return from_text(text.str());
}

Script Script::from_text(const std::string& text) {
  Script script;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) script.commands_.push_back(line);
  }
  return script;
}

std::string Script::before_frame(Viewer& viewer) {
  if (frames_to_wait_ > 0) {
    --frames_to_wait_;
    return "";
  }
  while (!commands_.empty()) {
    std::istringstream words(commands_.front());
    std::string command, argument;
    words >> command >> argument;
    if (command == "wait" || command == "wait-idle") {
      if (viewer.busy()) return "";  // ask again next frame
      commands_.pop_front();
      if (command == "wait" && !viewer.has_reconstruction()) {
        std::cerr << "sculpt-view: script: no reconstruction: " << viewer.message() << '\n';
        failed_ = true;
      }
      continue;
    }
    commands_.pop_front();
    if (command == "example") {
      viewer.open_example(argument);
    } else if (command == "open") {
      viewer.open_file(argument);
    } else if (command == "stage") {
      scene::Stage stage;
      if (!scene::parse_stage(argument, stage)) {
        std::cerr << "sculpt-view: script: no stage '" << argument << "'\n";
        failed_ = true;
        continue;
      }
      viewer.set_stage(stage);
    } else if (command == "next") {
      viewer.step_stage(+1);
    } else if (command == "previous") {
      viewer.step_stage(-1);
    } else if (command == "step") {
      viewer.set_step(std::stol(argument));
    } else if (command == "pick-sample") {
      viewer.pick_sample(std::stoi(argument));
    } else if (command == "pick-pole") {
      viewer.pick_pole(std::stoi(argument));
    } else if (command == "figure") {
      failed_ = !viewer.open_figure(argument) || failed_;
    } else if (command == "panel") {
      failed_ = !viewer.go_to_panel(argument) || failed_;
    } else if (command == "expect-panel") {
      if (viewer.panel_on_screen() != argument) {
        std::cerr << "sculpt-view: script: expected panel " << argument << " on screen, not '"
                  << viewer.panel_on_screen() << "' (" << viewer.message() << ")\n";
        failed_ = true;
      }
    } else if (command == "key") {
      const int key = key_code(argument);
      if (key < 0) {
        std::cerr << "sculpt-view: script: no key '" << argument << "'\n";
        failed_ = true;
      } else {
        viewer.press_key(key);
      }
    } else if (command == "animation") {
      viewer.set_animation(argument != "off");
    } else if (command == "frames") {
      frames_to_wait_ = std::max(0, std::stoi(argument) - 1);
      return "";
    } else if (command == "screenshot") {
      return argument;
    } else if (command == "export") {
      std::string size;
      words >> size;
      int width = 800, height = 600;
      if (!size.empty()) std::sscanf(size.c_str(), "%dx%d", &width, &height);
      failed_ = !viewer.export_picture(argument, width, height) || failed_;
    } else if (command == "cancel") {
      viewer.cancel();
    } else if (command == "expect-busy") {
      if (!viewer.busy()) {
        std::cerr << "sculpt-view: script: expected a reconstruction to be running\n";
        failed_ = true;
      }
    } else if (command == "quit") {
      commands_.clear();
      return "";
    } else {
      std::cerr << "sculpt-view: script: unknown command '" << command << "'\n";
      failed_ = true;
    }
  }
  return "";
}

}  // namespace sculpt::viewer
