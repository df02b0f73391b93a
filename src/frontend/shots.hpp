// Shots read from JSON, and a renderer of shots that reconstructs each input once however many
// shots show it (`sculpt render`, `sculpt figures`).
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "frontend/input.hpp"
#include "frontend/shot.hpp"
#include "render/headless.hpp"
#include "scene/scene.hpp"

namespace sculpt::frontend {

// A picture size "WIDTHxHEIGHT"; throws io::Error with a one-line message.
std::pair<int, int> parse_size(const std::string& size);

// Reads a JSON file; throws io::Error with a one-line message.
nlohmann::json read_json(const std::string& path);

// Why a shot's output cannot be written ("" if it can): a picture is a .png, an animation a
// .webp.
std::string output_format_problem(const Shot& shot);

// Reads a shot's fields from JSON (the names of Shot's members; "legend": false for no legend).
Shot shot_from_json(const nlohmann::json& json);

using Any_reconstruction = std::variant<Reconstruction<2>, Reconstruction<3>>;

// An input's points reconstructed, in their dimension.
Any_reconstruction reconstruct_input(const Input& input, const Options& options);

// A picture of a stage of a reconstruction as a shot describes it (the shot's input, method and
// output are not read): the scene drawn, the camera, the image.
struct Picture {
  scene::Scene scene;
  render::Camera camera;
  render::Image image;
};
// `camera`, if given, replaces the fitted camera. Throws io::Error with a one-line message.
Picture draw_shot(render::Headless_renderer& renderer, const Shot& shot,
                  const Any_reconstruction& reconstruction, const nlohmann::json* camera = nullptr);

class Shot_renderer {
 public:
  // Renders a shot to its output PNG. `camera`, if given, replaces the fitted camera.
  // Returns the scene that was drawn. Throws io::Error with a one-line message.
  scene::Scene render(const Shot& shot, const nlohmann::json* camera = nullptr);
  // The reconstruction a shot shows (made once per input and options).
  const Any_reconstruction& reconstruction(const Shot& shot);

 private:
  std::map<std::string, Any_reconstruction> cache_;
  std::unique_ptr<render::Headless_renderer> renderer_;
};

}  // namespace sculpt::frontend
