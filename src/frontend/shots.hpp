// SPDX-License-Identifier: GPL-3.0-or-later
// Shots read from JSON, checked, and drawn from a reconstruction into pictures and animations
// through any picture renderer: the headless one (frontend/shot_renderer.hpp: `sculpt render`,
// `sculpt figures`) or the viewer's window (its exports, on the desktop and in the browser).
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "frontend/input.hpp"
#include "frontend/shot.hpp"
#include "render/picture_renderer.hpp"
#include "scene/scene.hpp"

namespace sculpt::frontend {

// A picture size "WIDTHxHEIGHT"; throws io::Error with a one-line message.
std::pair<int, int> parse_size(const std::string& size);

// Reads a JSON file; throws io::Error with a one-line message.
nlohmann::json read_json(const std::string& path);

// Why a shot's output cannot be written ("" if it can): a picture is a .png, an animation a
// .webp or a .gif.
std::string output_format_problem(const Shot& shot);

// Reads a shot's fields from JSON (the names of Shot's members; "legend": false for no legend).
Shot shot_from_json(const nlohmann::json& json, const std::string& name = "the shot");

// A picture of a stage of a reconstruction as a shot describes it (the shot's input, method and
// output are not read): the scene drawn, the camera, the image.
struct Picture {
  scene::Scene scene;
  render::Camera camera;  // as drawn: a fitted camera after its steps back for the legend
  render::Image image;
  int legend_steps = 0;  // the steps back (render::legend_step_back each) from the fit, in all
};
// What a shot asks of the scene builder: its stage, step, focus, clip, layers and drawing options.
// Throws io::Error with a one-line message (an unknown stage, a malformed clip, ...).
scene::Request request_of(const Shot& shot);

// What can be known of a shot once its reconstruction is: a clip asks for a 3D one. Throws
// io::Error with a one-line message.
void check_shot_applies(const Shot& shot, const Any_reconstruction& reconstruction);

// The scene a shot draws of a reconstruction (after check_shot_applies). Throws io::Error with
// a one-line message.
scene::Scene scene_of(const Shot& shot, const Any_reconstruction& reconstruction);

// The shots of an animation's pictures: the replay's steps, or the method's stages (those of a
// 3D triangulation or diagram in section, facing the camera, unless the shot cuts or sections).
std::vector<Shot> animation_frames(const Shot& shot, const Any_reconstruction& reconstruction);

// `camera`, if given, replaces the fitted camera. A fitted camera steps back for the legend
// (render::with_room_for_legend); `legend_steps_before`, the steps an animation's earlier frames
// took, starts it that far back, and render::legend_steps_at_most is all it takes in all. Throws
// io::Error with a one-line message.
Picture draw_shot(render::Picture_renderer& renderer, const Shot& shot,
                  const Any_reconstruction& reconstruction, const nlohmann::json* camera = nullptr,
                  int legend_steps_before = 0);

// The same, of a scene already built by scene_of (what was checked is what is drawn).
Picture draw_scene(render::Picture_renderer& renderer, const Shot& shot, scene::Scene scene,
                   const nlohmann::json* camera = nullptr, int legend_steps_before = 0);

// What can be known of a shot before any work: its output's format and folder, its stage, size
// and animation. Throws io::Error with a one-line message.
void check_shot(const Shot& shot);

// Writes a shot of `reconstruction` to its output: a PNG, or an animated WebP of the replay or
// the stages (shot.animate), all or nothing; the camera too where the shot asks (save_camera;
// an animation's first picture's).
// Returns the (last) scene drawn. A picture's scene already built by scene_of (to check it) is
// drawn as it is. Throws io::Error with a one-line message.
scene::Scene write_shot(render::Picture_renderer& renderer, const Shot& shot,
                        const Any_reconstruction& reconstruction,
                        const nlohmann::json* camera = nullptr,
                        std::optional<scene::Scene> built = std::nullopt);

}  // namespace sculpt::frontend
