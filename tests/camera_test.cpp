// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's camera (render::follow_point): it keeps the action in view without losing the
// shape, and leaves alone a zoom the user chose.
#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sculpt {
namespace {

using render::Follow;

render::Camera fitted(int dimension) {
  scene::Scene box;
  box.dimension = dimension;
  box.lower = {-1, -1, dimension == 3 ? -1.0f : 0.0f};
  box.upper = {1, 1, dimension == 3 ? 1.0f : 0.0f};
  return render::fit(box, 1.0f);
}

// Whether a point is on screen (in front of a 3D camera, within the picture).
bool in_view(const render::Camera& camera, const glm::vec3& point) {
  const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(point, 1.0f);
  return clip.w > 0 && std::abs(clip.x / clip.w) <= 1 && std::abs(clip.y / clip.w) <= 1;
}

const glm::vec3 lower{-1, -1, 0}, upper{1, 1, 0};

TEST(Follow_point, AFarSeedIsFramedWithTheShapeAndTheCameraThenReturns) {
  render::Camera camera = fitted(2);
  const render::Camera start = camera;
  EXPECT_EQ(render::follow_point(camera, {0.5f, 0.5f, 0}, lower, upper, 1.0f, false),
            Follow::stayed);
  EXPECT_TRUE(render::same_view(camera, start));

  const glm::vec3 seed{9, -7, 0};
  EXPECT_EQ(render::follow_point(camera, seed, lower, upper, 1.0f, false), Follow::framed_far);
  EXPECT_TRUE(in_view(camera, seed));
  EXPECT_TRUE(in_view(camera, lower));
  EXPECT_TRUE(in_view(camera, upper));

  // Back near the shape: the camera a far seed framed frames the shape again.
  EXPECT_EQ(render::follow_point(camera, {0.2f, 0.1f, 0}, lower, upper, 1.0f, true),
            Follow::returned);
  EXPECT_NEAR(camera.half_height, start.half_height, 1e-4f);
}

TEST(Follow_point, AZoomTheUserChoseStays) {
  render::Camera camera = fitted(2);
  camera.zoom(3.0f);  // zoomed out by hand
  const render::Camera chosen = camera;
  EXPECT_EQ(render::follow_point(camera, {0.2f, 0.1f, 0}, lower, upper, 1.0f, false),
            Follow::stayed);
  EXPECT_TRUE(render::same_view(camera, chosen));
  camera.zoom(1.0f / 30.0f);  // zoomed in on a detail: a point near the shape is panned to
  EXPECT_EQ(render::follow_point(camera, {0.9f, 0.9f, 0}, lower, upper, 1.0f, false),
            Follow::panned);
  EXPECT_NEAR(camera.half_height, chosen.half_height / 30.0f, 1e-5f);
  EXPECT_TRUE(in_view(camera, {0.9f, 0.9f, 0}));
}

TEST(Follow_point, A3dSeedBehindTheCameraIsFramedToo) {
  render::Camera camera = fitted(3);
  const glm::vec3 eye = camera.eye();
  const glm::vec3 behind = eye + 3.0f * (eye - camera.target);  // far, behind the eye
  ASSERT_FALSE(in_view(camera, behind));
  EXPECT_EQ(render::follow_point(camera, behind, {-1, -1, -1}, {1, 1, 1}, 1.0f, false),
            Follow::framed_far);
  EXPECT_TRUE(in_view(camera, behind));
}

}  // namespace
}  // namespace sculpt
