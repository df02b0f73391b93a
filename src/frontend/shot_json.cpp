// SPDX-License-Identifier: GPL-3.0-or-later
// Shots read from JSON (frontend/shots.hpp): every field with the type it must have, every key
// one a shot takes.
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "frontend/shots.hpp"
#include "io/io_error.hpp"

namespace sculpt::frontend {

namespace {

// A shot's fields read with the type each must have: a wrong type, or a number out of the
// field's range, is one line naming the shot, the key and what it takes; never the JSON
// library's own error, and never a number wrapped into another.
class Shot_fields {
 public:
  Shot_fields(const nlohmann::json& json, std::string name) : json_(json), name_(std::move(name)) {
    if (!json.is_object()) throw io::Error(name_ + " is not a JSON object of fields");
  }

  std::string text(const char* key, const std::string& fallback) const {
    const auto* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) refuse(key, "text in quotes", *value);
    return value->get<std::string>();
  }
  bool flag(const char* key, bool fallback) const {
    const auto* value = find(key);
    if (!value) return fallback;
    if (!value->is_boolean()) refuse(key, "true or false", *value);
    return value->get<bool>();
  }
  long whole(const char* key, long fallback, long lowest, long highest) const {
    const auto* value = find(key);
    if (!value) return fallback;
    const std::string range =
        "a whole number from " + std::to_string(lowest) + " to " + std::to_string(highest);
    // JSON reads 7 as unsigned and -7 as signed; 1e300 and 2.5 are not whole numbers.
    if (value->is_number_unsigned()) {
      const auto number = value->get<std::uint64_t>();
      if (number <= static_cast<std::uint64_t>(highest) && static_cast<long>(number) >= lowest)
        return static_cast<long>(number);
    } else if (value->is_number_integer()) {
      const auto number = value->get<std::int64_t>();
      if (number >= lowest && number <= highest) return static_cast<long>(number);
    }
    refuse(key, range, *value);
  }
  double number(const char* key, double fallback) const {
    const auto* value = find(key);
    if (!value) return fallback;
    if (!value->is_number()) refuse(key, "a number", *value);
    return value->get<double>();
  }
  std::vector<std::string> texts(const char* key) const {
    const auto* value = find(key);
    if (!value) return {};
    if (!value->is_array()) refuse(key, "a list of names in quotes", *value);
    std::vector<std::string> texts;
    for (const auto& item : *value) {
      if (!item.is_string()) refuse(key, "a list of names in quotes", *value);
      texts.push_back(item.get<std::string>());
    }
    return texts;
  }

 private:
  const nlohmann::json* find(const char* key) const {
    read_.insert(key);
    const auto found = json_.find(key);
    return found == json_.end() || found->is_null() ? nullptr : &*found;
  }
  [[noreturn]] void refuse(const char* key, const std::string& takes,
                           const nlohmann::json& value) const {
    std::string shown = value.dump();
    if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
    throw io::Error(name_ + ": \"" + key + "\" takes " + takes + ", not " + shown);
  }

  const nlohmann::json& json_;
  std::string name_;
  mutable std::set<std::string> read_;

 public:
  // After every field was read: a key that is none of them (a typo: "stag") is refused, with
  // the keys a shot takes, rather than silently ignored.
  void refuse_unknown_keys(const std::set<std::string>& also_known) const {
    for (const auto& item : json_.items()) {
      if (read_.count(item.key()) || also_known.count(item.key())) continue;
      std::set<std::string> known = read_;
      known.insert(also_known.begin(), also_known.end());
      std::string keys;
      for (const auto& key : known) keys += (keys.empty() ? "" : ", ") + key;
      throw io::Error(name_ + ": no field \"" + item.key() + "\" (a shot takes " + keys + ")");
    }
  }
};

}  // namespace

Shot shot_from_json(const nlohmann::json& j, const std::string& name) {
  const Shot_fields f(j, name);
  constexpr long most = std::numeric_limits<int>::max();
  Shot shot;
  shot.input = f.text("input", "");
  shot.example = f.text("example", "");
  shot.bordered = f.flag("bordered", false);
  shot.closed = f.flag("closed", false);
  shot.dimension = static_cast<int>(f.whole("dimension", 0, 0, 3));
  shot.stage = f.text("stage", shot.stage);
  shot.step = f.whole("step", -1, -1, most);
  shot.focus_sample = static_cast<int>(f.whole("focus_sample", -1, -1, most));
  shot.focus_pole = static_cast<int>(f.whole("focus_pole", -1, -1, most));
  shot.method = f.text("method", shot.method);
  shot.box_factor = f.number("box_factor", shot.box_factor);
  shot.alpha = f.number("alpha", shot.alpha);
  shot.merge_duplicates = f.flag("merge_duplicates", false);
  shot.rule = f.text("rule", shot.rule);
  shot.clean = f.text("clean", shot.clean);
  shot.layers = f.texts("layers");
  shot.clip = f.text("clip", "");
  shot.section = f.text("section", "");
  shot.camera_file = f.text("camera_file", "");
  shot.save_camera = f.text("save_camera", "");
  shot.size = f.text("size", shot.size);
  shot.wireframe = f.flag("wireframe", false);
  shot.smooth = f.flag("smooth", false);
  shot.no_legend = !f.flag("legend", true);
  shot.zoom = f.number("zoom", shot.zoom);
  shot.ball_every = static_cast<int>(f.whole("ball_every", 1, 1, most));
  shot.polar_balls = f.flag("polar_balls", false);
  shot.ball_limit = static_cast<int>(f.whole("ball_limit", 0, 0, most));
  shot.palette = f.text("palette", shot.palette);
  shot.ball_opacity = f.number("ball_opacity", shot.ball_opacity);
  shot.neighbourhood = f.flag("neighbourhood", false);
  shot.yaw = f.number("yaw", shot.yaw);
  shot.pitch = f.number("pitch", shot.pitch);
  shot.title = f.text("title", "");
  shot.animate = f.text("animate", "");
  shot.frames = static_cast<int>(f.whole("frames", shot.frames, 0, most));
  shot.frame_ms = static_cast<int>(f.whole("frame_ms", shot.frame_ms, 0, most));
  shot.output = f.text("output", "");
  f.refuse_unknown_keys({"camera"});  // an inline camera, read with the shot's scene
  return shot;
}

}  // namespace sculpt::frontend
