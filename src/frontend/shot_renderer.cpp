// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/shot_renderer.hpp"

#include "frontend/input.hpp"
#include "io/io_error.hpp"

namespace sculpt::frontend {

scene::Scene Shot_renderer::render(const Shot& shot, const nlohmann::json* camera) {
  check_shot(shot);  // before any work
  if (shot.input.empty() == shot.example.empty()) {
    throw io::Error("a shot needs an input file or an example (one of them)");
  }
  const Any_reconstruction& shown = reconstruction(shot);
  check_shot_applies(shot, shown);  // before a renderer is made
  if (!renderer_) renderer_ = std::make_unique<render::Headless_renderer>();
  return write_shot(*renderer_, shot, shown, camera);
}

const Any_reconstruction& Shot_renderer::reconstruction(const Shot& shot) {
  const std::string key = shot.input + "|" + shot.example + "|" + to_string(kind_of(shot)) + "|" +
                          std::to_string(shot.dimension) + "|" + std::to_string(shot.box_factor) +
                          "|" + shot.rule + "|" + shot.method + "|" + std::to_string(shot.alpha) +
                          "|" + std::to_string(shot.merge_duplicates);
  auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  const frontend::Input input =
      frontend::load_input(shot.input, shot.example, shot.dimension, shot.merge_duplicates);
  Options options;
  if (!parse_method(shot.method, options.method)) {
    std::string names;
    for (const char* name : method_names()) names += std::string(names.empty() ? "" : ", ") + name;
    throw io::Error("no method '" + shot.method + "' (methods: " + names + ")");
  }
  if (!parse_rule(shot.rule, options.rule)) {
    throw io::Error("no surface rule '" + shot.rule + "' (rules: auto, skin, extraction)");
  }
  // An example is reconstructed as its own kind, as in the viewer and the command line.
  options.kind = kind_of(shot);
  options.box_factor = shot.box_factor;
  options.alpha = shot.alpha;
  Any_reconstruction result = reconstruct_input(input, options);
  return cache_.emplace(key, std::move(result)).first->second;
}

}  // namespace sculpt::frontend
