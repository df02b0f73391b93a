// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_line.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace sculpt::viewer {

std::optional<long> number(const std::string& word, long low, long high) {
  long value = 0;
  const char* end = word.data() + word.size();
  const auto [stop, error] = std::from_chars(word.data(), end, value);
  if (word.empty() || error != std::errc() || stop != end || value < low || value > high) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::pair<int, int>> picture_size(const std::string& word) {
  const auto x = word.find('x');
  if (x == std::string::npos) return std::nullopt;
  const auto width = number(word.substr(0, x), 16, 8192);
  const auto height = number(word.substr(x + 1), 16, 8192);
  if (!width || !height) return std::nullopt;
  return std::pair<int, int>(int(*width), int(*height));
}

std::optional<double> real(const std::string& word) {
  if (word.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool takes_arguments(const std::string& command) {
  for (const char* name : {"export", "export-animation", "clip", "section", "add-point",
                           "move-point", "stroke", "layer", "camera", "replay"}) {
    if (command == name) return true;
  }
  return false;
}

Script_line::Script_line(const std::string& text, Viewer& viewer, Failure fail)
    : text(text), words(text), viewer(viewer), fail_(std::move(fail)) {
  words >> command >> argument >> extra;
  std::istringstream all(text);
  std::string word;
  all >> word;
  while (all >> word) arguments.push_back(word);
}

std::optional<std::vector<double>> Script_line::reals(std::size_t first) const {
  std::vector<double> values;
  for (std::size_t i = first; i < arguments.size(); ++i) {
    const auto value = real(arguments[i]);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

bool Script_line::needs_argument(const char* what) const {
  if (!argument.empty()) return true;
  fail("'" + command + "' needs " + what);
  return false;
}

std::optional<long> Script_line::count(const char* what, long low, long high) const {
  if (!needs_argument(what)) return std::nullopt;
  const auto value = number(argument, low, high);
  if (!value) fail("'" + text + "': expected " + what);
  return value;
}

void Script_line::done(bool succeeded) const {
  if (!succeeded) fail("'" + text + "': " + viewer.message());
}

void Script_line::on_off(const std::function<void(bool)>& set) const {
  if (argument == "on" || argument == "off") {
    set(argument == "on");
  } else {
    fail("'" + text + "': expected " + command + " on or off");
  }
}

}  // namespace sculpt::viewer
