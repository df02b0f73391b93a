// SPDX-License-Identifier: GPL-3.0-or-later
// One line of a viewer script split into its words, and the checks every command makes of its
// arguments: each prints one line and fails the script when it did not get what it needs.
#pragma once

#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "viewer.hpp"

namespace sculpt::viewer {

// A whole word as a number in [low, high], or nothing.
std::optional<long> number(const std::string& word, long low, long high);
// A picture size WIDTHxHEIGHT, 16 to 8192 pixels each, or nothing.
std::optional<std::pair<int, int>> picture_size(const std::string& word);
// A whole word as a finite real number, or nothing.
std::optional<double> real(const std::string& word);
// Commands that take more than one argument parse their own.
bool takes_arguments(const std::string& command);

class Script_line {
 public:
  using Failure = std::function<void(const std::string&)>;
  Script_line(const std::string& text, Viewer& viewer, Failure fail);

  const std::string text;
  std::string command, argument, extra;  // the first three words
  std::vector<std::string> arguments;    // every word after the command
  std::istringstream words;              // past the first three, for commands that read on
  Viewer& viewer;

  void fail(const std::string& why) const { fail_(why); }
  // Arguments read as real numbers from `first` on; nothing if one is not a number.
  std::optional<std::vector<double>> reals(std::size_t first) const;
  bool needs_argument(const char* what) const;
  std::optional<long> count(const char* what, long low, long high) const;
  void done(bool succeeded) const;
  // A switch: `command on` or `command off`.
  void on_off(const std::function<void(bool)>& set) const;

 private:
  Failure fail_;
};

// The groups of commands, each in a file of its own: true when the command is one of theirs.
bool run_view_command(Script_line& line);    // what is shown and how (script_view_commands.cpp)
bool run_output_command(Script_line& line);  // files written, lines printed
bool run_edit_command(Script_line& line);    // 2D samples edited by hand

}  // namespace sculpt::viewer
