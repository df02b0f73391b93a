// SPDX-License-Identifier: GPL-3.0-or-later
// The view on screen as the options that open it again: a link to the viewer in the browser
// (?example=torus&method=paper&stage=poles), the command line on the desktop (sculpt-view
// --example torus --method paper --stage poles). main.cpp reads both the same way.
#include <cctype>
#include <cstdio>
#include <sstream>

#include "platform/platform.hpp"
#include "shapes/shapes.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

namespace {

// A query's value, percent-encoded where it is not a plain word.
std::string encoded(const std::string& value) {
  static const char* hex = "0123456789ABCDEF";
  std::string text;
  for (unsigned char c : value) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      text += char(c);
    } else {
      text += '%';
      text += hex[c >> 4];
      text += hex[c & 15];
    }
  }
  return text;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> Viewer::view_options(std::string& why_not) const {
  std::vector<std::pair<std::string, std::string>> options;
  why_not.clear();
  if (tour_.active() && !tour_.exploring()) {
    options.push_back({"figure", tour_.figure().id});
    options.push_back({"panel", std::to_string(tour_.panel() + 1)});
    return options;
  }
  if (!reconstruction_) {
    why_not = "nothing is shown yet";
    return options;
  }
  if (shown_request_.edited_points || shown_request_.example.empty()) {
    why_not = shown_request_.edited_points
                  ? "edited samples exist only here: save them (File menu) to hand them out"
                  : "a file from this computer cannot be linked: only the built-in examples";
    return options;
  }
  options.push_back({"example", shown_request_.example});
  const Options& shown = options_of(*reconstruction_);
  if (shown.method != Options{}.method) options.push_back({"method", to_string(shown.method)});
  // The kind, where it is not the example's own.
  const shapes::Example* example = shapes::find_example(shown_request_.example);
  const Surface_kind own = frontend::input_kind(example, false, false);
  if (shown_request_.options.kind != own && shown_request_.options.kind != Surface_kind::automatic)
    options.push_back({"kind", to_string(shown_request_.options.kind)});
  if (request_.stage != scene::Stage::surface)
    options.push_back({"stage", scene::stage_id(request_.stage)});
  if (scene::replays(request_.stage) && request_.step >= 0)
    options.push_back({"step", std::to_string(request_.step)});
  if (request_.focus_sample >= 0)
    options.push_back({"sample", std::to_string(request_.focus_sample)});
  return options;
}

std::string Viewer::link_to_view(std::string& why_not) const {
  auto options = view_options(why_not);
  if (options.empty()) return "";
  // The text size chosen for a projector goes with the view it was chosen for.
  const float text_scale = ImGui::GetIO().FontGlobalScale;
  const auto scale_text = [](float scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(scale));
    return std::string(text);
  };
  if (text_scale != 1.0f) options.push_back({"text", scale_text(text_scale)});
  // So does a presentation: a link a teacher opens in front of the class.
  if (presenting_) options.push_back({"present", "on"});
  if (colour_blind_) options.push_back({"palette", "colour-blind"});
  if (picture_scale_ != 1.0f) options.push_back({"scale", scale_text(picture_scale_)});
  std::ostringstream text;
  if (platform::in_browser) {
    text << platform::page_address();
    char separator = '?';
    for (const auto& [key, value] : options) {
      text << separator << key << '=' << encoded(value);
      separator = '&';
    }
  } else {
    // The command line's names: sample is --pick-sample, kind is --closed or --bordered,
    // present is --present.
    text << "sculpt-view";
    for (const auto& [key, value] : options) {
      if (key == "kind") {
        text << " --" << value;
      } else if (key == "present") {
        text << " --present";
      } else {
        const std::string option = key == "sample"  ? "pick-sample"
                                   : key == "text"  ? "font-scale"
                                   : key == "scale" ? "picture-scale"
                                                    : key;
        text << " --" << option << ' ' << value;
      }
    }
  }
  return text.str();
}

void Viewer::copy_link_to_view() {
  std::string why_not;
  const std::string link = link_to_view(why_not);
  if (link.empty()) {
    message_ = "no link to this view: " + why_not;
    return;
  }
  platform::copy_text(link);
  message_ = std::string(platform::in_browser ? "link" : "command") + " copied: " + link;
}

}  // namespace sculpt::viewer
