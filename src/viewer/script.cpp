// SPDX-License-Identifier: GPL-3.0-or-later
#include "script.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "io/point_reader.hpp"
#include "script_line.hpp"

namespace sculpt::viewer {

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
    Script_line current(commands_.front().line, viewer,
                        [this](const std::string& why) { fail(why); });
    const std::string& command = current.command;
    const std::string& argument = current.argument;
    const std::string& line = current.text;
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
    if (!current.extra.empty() && !takes_arguments(command)) {
      fail("'" + line + "': one argument expected");
      continue;
    }
    if (command == "help") {
      std::cout
          << "commands: example NAME, open FILE, method NAME, clean "
             "auto|none|outliers|jet|outliers+jet, "
             "stage ID, next, "
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
    } else if (command == "frames") {
      if (const auto frames = current.count("a number of frames (1 to 100000)", 1, 100000)) {
        frames_to_wait_ = int(*frames) - 1;
        return "";
      }
    } else if (command == "screenshot") {
      if (!current.needs_argument("a PNG path")) continue;
      // Written as the extension says, or refused: never PNG bytes under another name.
      if (io::extension_of(argument) != ".png") {
        fail("'" + line + "': a screenshot is a PNG image: the path must end in .png");
        continue;
      }
      return argument;
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
    } else if (!run_view_command(current) && !run_output_command(current) &&
               !run_edit_command(current)) {
      fail("unknown command '" + command + "' (`help` lists them)");
    }
  }
  return "";
}

}  // namespace sculpt::viewer
