// SPDX-License-Identifier: GPL-3.0-or-later
// A renderer of shots that reconstructs each input once however many shots show it, and draws
// them headless (`sculpt render`, `sculpt figures`).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "frontend/option_use.hpp"
#include "frontend/shots.hpp"
#include "render/headless.hpp"

namespace sculpt::frontend {

class Shot_renderer {
 public:
  // Renders a shot to its output PNG (or animation). `camera`, if given, replaces the fitted
  // camera. Returns the scene that was drawn. Throws io::Error with a one-line message.
  // An option that does nothing in this shot is refused, named as `spelling` says.
  scene::Scene render(const Shot& shot, const nlohmann::json* camera = nullptr,
                      Spelling spelling = Spelling::command_line);
  // The reconstruction a shot shows (made once per input and options).
  const Any_reconstruction& reconstruction(const Shot& shot);

  // What can be refused of a shot's options before any work (frontend/option_use.hpp): a
  // usage error on the command line, io::Error in a shots file.
  static void check_options(const Shot& shot, Spelling spelling);

 private:
  // The reconstruction options a shot asks for; throws io::Error for an unknown method or rule.
  static Options options_of(const Shot& shot);

  std::map<std::string, Any_reconstruction> cache_;
  std::unique_ptr<render::Headless_renderer> renderer_;
};

}  // namespace sculpt::frontend
