// A shot: one picture of one stage of one input, as `sculpt render`, the viewer's "save
// picture" and `sculpt figures` describe it; and a renderer of shots that reconstructs each
// input once however many shots show it.
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "render/headless.hpp"
#include "scene/scene.hpp"

namespace sculpt::frontend {

struct Shot {
  std::string input, example;
  bool bordered = false;
  int dimension = 0;
  std::string stage = "surface";
  long step = -1;
  int focus_sample = -1, focus_pole = -1;
  std::string method = to_string(Options{}.method);
  double box_factor = Options{}.box_factor;
  std::string rule = "auto";
  std::vector<std::string> layers;
  std::string camera_file, save_camera;
  std::string size = "800x800";
  bool wireframe = false, smooth = false, no_legend = false;
  float zoom = 1.0f;                // applied to the fitted camera (< 1 zooms in)
  int ball_every = 1;               // polar balls of every k-th pole only
  float yaw = 0.6f, pitch = 0.35f;  // 3D: direction the fitted camera looks from (radians)
  std::string output;
};

// Reads a JSON file; throws io::Error with a one-line message.
nlohmann::json read_json(const std::string& path);

// Reads a shot's fields from JSON (the names of Shot's members; "legend": false for no legend).
Shot shot_from_json(const nlohmann::json& json);

using Any_reconstruction = std::variant<Reconstruction<2>, Reconstruction<3>>;

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
