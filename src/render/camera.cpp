// SPDX-License-Identifier: GPL-3.0-or-later
#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

namespace sculpt::render {

glm::vec3 Camera::eye() const {
  const glm::vec3 direction(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                            std::cos(pitch) * std::cos(yaw));
  return target + distance * direction;
}

glm::mat4 Camera::view() const {
  if (dimension == 2) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(-center, 0.0f));
  }
  return glm::lookAt(eye(), target, glm::vec3(0, 1, 0));
}

glm::mat4 Camera::projection(float aspect) const {
  if (dimension == 2) {
    const float w = half_height * aspect;
    return glm::ortho(-w, w, -half_height, half_height, -1.0f, 1.0f);
  }
  return glm::perspective(glm::radians(fov_degrees), aspect, distance * 0.01f, distance * 100.0f);
}

namespace {

// Where a point falls on screen (x and y from -1 to 1 across the picture) and its depth; a depth
// of 0 or less: behind a 3D camera.
struct Projected {
  glm::vec2 ndc;
  float depth;
};

Projected project(const Camera& camera, const glm::vec3& point, float aspect) {
  const glm::vec4 clip = camera.projection(aspect) * camera.view() * glm::vec4(point, 1.0f);
  return {clip.w > 0 ? glm::vec2(clip) / clip.w : glm::vec2(0.0f), clip.w};
}

bool within(const glm::vec2& ndc, float edge) {
  return std::abs(ndc.x) <= edge && std::abs(ndc.y) <= edge;
}

}  // namespace

bool keep_in_view(Camera& camera, const glm::vec3& point, float aspect, float edge, float inside) {
  const auto [ndc, depth] = project(camera, point, aspect);
  if (depth <= 0 || within(ndc, edge)) return false;
  const float dx = ndc.x - std::clamp(ndc.x, -inside, inside);
  const float dy = ndc.y - std::clamp(ndc.y, -inside, inside);
  // pan() moves by the visible half height at the target; a point at another depth moves on
  // screen by target distance / its depth as much (its depth is 1 in 2D).
  const float scale = camera.dimension == 3 ? depth / camera.distance : 1.0f;
  camera.pan(dx * aspect * scale, dy * scale);
  return true;
}

namespace {

// The camera looking as `camera` does (its direction and field of view), framing the box
// [lower, upper].
Camera framing(const Camera& camera, const glm::vec3& lower, const glm::vec3& upper, float aspect) {
  scene::Scene box;
  box.dimension = camera.dimension;
  box.lower = {lower.x, lower.y, lower.z};
  box.upper = {upper.x, upper.y, upper.z};
  Camera framed = fit(box, aspect);
  const auto half_angle = [&](float fov) { return glm::radians(fov) / 2 * std::min(1.0f, aspect); };
  framed.distance *=
      std::sin(half_angle(framed.fov_degrees)) / std::sin(half_angle(camera.fov_degrees));
  framed.fov_degrees = camera.fov_degrees;
  framed.yaw = camera.yaw;
  framed.pitch = camera.pitch;
  return framed;
}

}  // namespace

Follow follow_point(Camera& camera, const glm::vec3& point, const glm::vec3& lower,
                    const glm::vec3& upper, float aspect, bool framed_far_before) {
  const glm::vec3 margin = 0.2f * (upper - lower);
  const bool near_the_shape = glm::all(glm::greaterThanEqual(point, lower - margin)) &&
                              glm::all(glm::lessThanEqual(point, upper + margin));
  if (near_the_shape) {
    if (framed_far_before) {
      camera = framing(camera, lower, upper, aspect);  // the seeds are done: back to the shape
      return Follow::returned;
    }
    return keep_in_view(camera, point, aspect) ? Follow::panned : Follow::stayed;
  }
  const auto [ndc, depth] = project(camera, point, aspect);
  if (depth > 0 && within(ndc, 0.85f)) return Follow::stayed;
  camera = framing(camera, glm::min(lower, point), glm::max(upper, point), aspect);
  return Follow::framed_far;
}

bool same_view(const Camera& a, const Camera& b) {
  return a.dimension == b.dimension && a.center == b.center && a.half_height == b.half_height &&
         a.target == b.target && a.distance == b.distance && a.yaw == b.yaw && a.pitch == b.pitch &&
         a.fov_degrees == b.fov_degrees;
}

void Camera::orbit(float yaw_delta, float pitch_delta) {
  yaw += yaw_delta;
  pitch = std::clamp(pitch + pitch_delta, -1.55f, 1.55f);
}

void Camera::pan(float right, float up) {
  if (dimension == 2) {
    center += glm::vec2(right, up) * half_height;
    return;
  }
  const glm::vec3 forward = glm::normalize(target - eye());
  const glm::vec3 side = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 vertical = glm::cross(side, forward);
  const float scale = distance * std::tan(glm::radians(fov_degrees) / 2);
  target += scale * (right * side + up * vertical);
}

void Camera::zoom(float factor) {
  if (dimension == 2) {
    half_height *= factor;
  } else {
    distance *= factor;
  }
}

Camera fit(const scene::Scene& scene, float aspect) {
  Camera camera;
  camera.dimension = scene.dimension;
  const glm::vec3 lower(scene.lower[0], scene.lower[1], scene.lower[2]);
  const glm::vec3 upper(scene.upper[0], scene.upper[1], scene.upper[2]);
  const glm::vec3 middle = 0.5f * (lower + upper);
  const glm::vec3 extent = upper - lower;
  if (scene.dimension == 2) {
    camera.center = glm::vec2(middle);
    camera.half_height = 0.55f * std::max({extent.y, extent.x / aspect, 1e-6f});
  } else {
    camera.target = middle;
    const float radius = 0.5f * std::max(glm::length(extent), 1e-6f);
    const float half_angle = glm::radians(camera.fov_degrees) / 2 * std::min(1.0f, aspect);
    camera.distance = 1.05f * radius / std::sin(half_angle);
  }
  return camera;
}

Camera fit(const scene::Scene& scene, float aspect, float zoom, float yaw, float pitch) {
  Camera camera = fit(scene, aspect);
  camera.yaw = yaw;
  camera.pitch = pitch;
  camera.zoom(zoom);
  return camera;
}

std::pair<float, float> yaw_pitch_along(const scene::Vec3& direction) {
  // eye() places the camera at target + distance * (cos p sin y, sin p, cos p cos y).
  const glm::vec3 d = glm::normalize(glm::vec3(direction[0], direction[1], direction[2]));
  const float pitch = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -1.55f, 1.55f);
  const float yaw = std::abs(d.x) + std::abs(d.z) > 1e-6f ? std::atan2(d.x, d.z) : 0.0f;
  return {yaw, pitch};
}

Camera interpolate(const Camera& a, const Camera& b, float t) {
  const auto geometric = [t](float x, float y) { return x * std::pow(y / x, t); };
  Camera c = b;
  c.center = glm::mix(a.center, b.center, t);
  c.half_height = geometric(a.half_height, b.half_height);
  c.target = glm::mix(a.target, b.target, t);
  c.distance = geometric(a.distance, b.distance);
  const float turn = std::remainder(b.yaw - a.yaw, 2.0f * glm::pi<float>());
  c.yaw = a.yaw + t * turn;
  c.pitch = glm::mix(a.pitch, b.pitch, t);
  return c;
}

nlohmann::json to_json(const Camera& c) {
  if (c.dimension == 2) {
    return {{"dimension", 2}, {"center", {c.center.x, c.center.y}}, {"half_height", c.half_height}};
  }
  return {{"dimension", 3},         {"target", {c.target.x, c.target.y, c.target.z}},
          {"distance", c.distance}, {"yaw", c.yaw},
          {"pitch", c.pitch},       {"fov_degrees", c.fov_degrees}};
}

Camera camera_from_json(const nlohmann::json& json) {
  try {
    Camera c;
    c.dimension = json.at("dimension").get<int>();
    if (c.dimension == 2) {
      c.center = {json.at("center").at(0).get<float>(), json.at("center").at(1).get<float>()};
      c.half_height = json.at("half_height").get<float>();
    } else if (c.dimension == 3) {
      const auto& t = json.at("target");
      c.target = {t.at(0).get<float>(), t.at(1).get<float>(), t.at(2).get<float>()};
      c.distance = json.at("distance").get<float>();
      c.yaw = json.at("yaw").get<float>();
      c.pitch = json.at("pitch").get<float>();
      c.fov_degrees = json.value("fov_degrees", c.fov_degrees);
    } else {
      throw std::invalid_argument("dimension must be 2 or 3");
    }
    return c;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("not a camera: ") + e.what());
  }
}

}  // namespace sculpt::render
