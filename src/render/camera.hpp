// SPDX-License-Identifier: GPL-3.0-or-later
// The camera of a picture: orthographic for 2D (centre and zoom), a perspective orbit for 3D
// (target, distance, yaw, pitch). It fits a scene's bounds, moves as the viewer's mouse asks,
// and saves to JSON so a shot can be repeated exactly.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <tuple>
#include <utility>

#include "scene/scene.hpp"

namespace sculpt::render {

struct Camera {
  int dimension = 3;
  // 3D orbit
  glm::vec3 target{0.0f};
  float distance = 3.0f;
  float yaw = 0.6f;     // radians around the vertical (y) axis
  float pitch = 0.35f;  // radians above the horizontal plane
  float fov_degrees = 35.0f;
  // 2D
  glm::vec2 center{0.0f};
  float half_height = 1.0f;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;

  void orbit(float yaw_delta, float pitch_delta);
  void pan(float right, float up);  // in units of the visible half height
  void zoom(float factor);          // < 1 zooms in
};

// A camera that shows the whole of the scene's bounds with a small margin.
Camera fit(const scene::Scene& scene, float aspect = 1.0f);
// The same, looking from (yaw, pitch) in 3D and zoomed by `zoom` (< 1 zooms in): a shot's camera.
Camera fit(const scene::Scene& scene, float aspect, float zoom, float yaw, float pitch);

// The yaw and pitch of a camera that looks along `direction` from its positive side (a section
// is seen so), the pitch kept short of the poles as orbit() keeps it.
std::pair<float, float> yaw_pitch_along(const scene::Vec3& direction);

// The camera a fraction t in [0, 1] of the way from a to b (same dimension): centres and targets
// move linearly, scale and distance geometrically, the orbit along the shorter way round.
Camera interpolate(const Camera& a, const Camera& b, float t);

// A point of a reconstruction (2 or 3 coordinates) where the renderer draws it: z = 0 in 2D.
template <class P>
glm::vec3 to_glm(const P& p) {
  constexpr std::size_t d = std::tuple_size_v<P>;
  return {float(p[0]), float(p[1]), d == 3 ? float(p[d - 1]) : 0.0f};
}

// Following a point (the replay's pole just labelled): if it lies beyond `edge` of the half
// view from the centre, pans the camera, keeping its zoom, until it lies within `inside`.
// Returns whether the camera moved (never for a point behind a 3D camera).
bool keep_in_view(Camera& camera, const glm::vec3& point, float aspect, float edge = 0.85f,
                  float inside = 0.6f);

// Following the replay without losing the shape. A point near the box [lower, upper] (the
// samples') is followed by keep_in_view, keeping the zoom; a point far out of view (a convex seed
// by a box corner, in front of or behind a 3D camera) makes the camera frame the box and the
// point together. Once the action is back near the shape, a camera that a far point framed, and
// nobody moved since (`framed_far_before`), frames the shape again; a zoom the user chose stays.
enum class Follow { stayed, panned, framed_far, returned };
Follow follow_point(Camera& camera, const glm::vec3& point, const glm::vec3& lower,
                    const glm::vec3& upper, float aspect, bool framed_far_before);
// Whether two cameras show the same view.
bool same_view(const Camera& a, const Camera& b);

nlohmann::json to_json(const Camera& camera);
Camera camera_from_json(const nlohmann::json& json);  // throws std::invalid_argument

}  // namespace sculpt::render
