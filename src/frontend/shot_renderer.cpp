// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/shot_renderer.hpp"

#include "frontend/command_line.hpp"
#include "frontend/input.hpp"
#include "frontend/option_use.hpp"
#include "io/io_error.hpp"

namespace sculpt::frontend {

namespace {

// A refusal in the caller's words: a usage error (exit 2) on the command line, bad input (exit
// 1) in a shots file.
void refuse_if(const std::string& problem, Spelling spelling) {
  if (problem.empty()) return;
  if (spelling == Spelling::command_line) throw Usage_error(problem);
  throw io::Error(problem);
}

}  // namespace

void Shot_renderer::check_options(const Shot& shot, Spelling spelling) {
  refuse_if(unused_animation_option(shot, spelling), spelling);
  refuse_if(unused_input_option(shot.example, shot.dimension, shot.merge_duplicates, spelling),
            spelling);
  refuse_if(unused_reconstruction_option(options_of(shot), spelling), spelling);
}

scene::Scene Shot_renderer::render(const Shot& shot, const nlohmann::json* camera,
                                   Spelling spelling) {
  check_shot(shot);  // before any work
  if (shot.input.empty() == shot.example.empty()) {
    throw io::Error("a shot needs an input file or an example (one of them)");
  }
  check_options(shot, spelling);
  const Any_reconstruction& shown = reconstruction(shot);
  check_shot_applies(shot, shown);  // before a renderer is made
  // What a picture draws says which drawing options do something (an animation's pictures
  // differ, each stage its own).
  std::optional<scene::Scene> scene;
  if (shot.animate.empty()) {
    scene = scene_of(shot, shown);
    refuse_if(unused_drawing_option(shot, *scene, spelling), spelling);
  }
  if (!renderer_) renderer_ = std::make_unique<render::Headless_renderer>();
  return write_shot(*renderer_, shot, shown, camera, std::move(scene));
}

const Any_reconstruction& Shot_renderer::reconstruction(const Shot& shot) {
  const std::string key = shot.input + "|" + shot.example + "|" + to_string(kind_of(shot)) + "|" +
                          std::to_string(shot.dimension) + "|" + std::to_string(shot.box_factor) +
                          "|" + shot.rule + "|" + shot.clean + "|" + shot.method + "|" +
                          std::to_string(shot.alpha) + "|" + std::to_string(shot.merge_duplicates);
  auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  const Options options = options_of(shot);
  const frontend::Input input =
      frontend::load_input(shot.input, shot.example, shot.dimension, shot.merge_duplicates);
  Any_reconstruction result = reconstruct_input(input, options);
  return cache_.emplace(key, std::move(result)).first->second;
}

Options Shot_renderer::options_of(const Shot& shot) {
  Options options;
  if (!parse_method(shot.method, options.method)) {
    std::string names;
    for (const char* name : method_names()) names += std::string(names.empty() ? "" : ", ") + name;
    throw io::Error("no method '" + shot.method + "' (methods: " + names + ")");
  }
  if (!parse_rule(shot.rule, options.rule)) {
    throw io::Error("no surface rule '" + shot.rule + "' (rules: auto, skin, extraction)");
  }
  if (!parse_cleaning(shot.clean, options.cleaning)) {
    throw io::Error("no cleaning '" + shot.clean + "' (cleanings: " + cleaning_choices() + ")");
  }
  // An example is reconstructed as its own kind, as in the viewer and the command line.
  options.kind = kind_of(shot);
  options.box_factor = shot.box_factor;
  options.alpha = shot.alpha;
  return options;
}

}  // namespace sculpt::frontend
