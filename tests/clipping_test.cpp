// SPDX-License-Identifier: GPL-3.0-or-later
// The cut-away plane of 3D stages: whole primitives whose centre lies beyond the plane go, the
// rest stay as they were; the plane's position runs across the samples' box along its normal.
#include "scene/clipping.hpp"

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

std::size_t positions_of(const scene::Scene& scene, const char* id) {
  for (const auto& layer : scene.layers) {
    if (layer.id == id) return layer.positions.size();
  }
  return 0;
}

TEST(Clipping, LeavesOutWhatLiesBeyondThePlane) {
  const auto result = reconstruct(shapes::bumpy_sphere(2000));
  scene::Request request;
  request.stage = scene::Stage::delaunay;
  const scene::Scene whole = scene::build_scene(result, request);
  const std::size_t edges = positions_of(whole, "delaunay");
  ASSERT_GT(edges, 0u);

  request.clipped = true;
  request.clip = {0.5f, 0.0f, 90.0f};  // the normal +z, through the middle of the samples' box
  const scene::Scene lower = scene::build_scene(result, request);
  const float middle = 0.5f * (whole.lower[2] + whole.upper[2]);
  for (const auto& layer : lower.layers) {
    const std::size_t per = layer.primitive == scene::Primitive::lines ? 2 : 1;
    for (std::size_t k = 0; k + per <= layer.positions.size(); k += per) {
      float z = 0;
      for (std::size_t j = 0; j < per; ++j) z += layer.positions[k + j][2] / float(per);
      EXPECT_LE(z, middle + 1e-5f) << layer.id;
    }
  }
  // About half of the edges stay (less those to the box corners), whole; the samples likewise.
  EXPECT_GT(positions_of(lower, "delaunay"), edges / 5);
  EXPECT_LT(positions_of(lower, "delaunay"), 3 * edges / 5);
  EXPECT_EQ(positions_of(lower, "delaunay") % 2, 0u);
  EXPECT_LT(positions_of(lower, "samples"), positions_of(whole, "samples"));
  EXPECT_EQ(lower.layers.size(), whole.layers.size());  // the legend does not change

  // Nothing beyond the plane: only the edges to the box corners, far outside the samples, go.
  request.clip.position = 1;
  const std::size_t near = positions_of(scene::build_scene(result, request), "delaunay");
  EXPECT_LT(near, edges);
  EXPECT_GT(near, edges / 2);
  EXPECT_EQ(positions_of(scene::build_scene(result, request), "samples"),
            positions_of(whole, "samples"));
  request.clip = {0.5f, 180.0f, 0.0f};  // the normal -x: the half on -x goes
  const scene::Scene right = scene::build_scene(result, request);
  const float middle_x = 0.5f * (whole.lower[0] + whole.upper[0]);
  for (const auto& layer : right.layers) {
    if (layer.id != "samples") continue;
    ASSERT_FALSE(layer.positions.empty());
    for (const auto& p : layer.positions) EXPECT_GE(p[0], middle_x - 1e-5f);
  }
}

TEST(Clipping, KeepsTrianglesWithTheirNormalsAndBallsWithTheirRadii) {
  scene::Scene scene;
  scene.lower = {0, 0, 0};
  scene.upper = {1, 1, 1};
  scene::Layer triangles;
  triangles.primitive = scene::Primitive::triangles;
  triangles.positions = {{0, 0, 0.1f}, {1, 0, 0.1f}, {0, 1, 0.1f},   // below the middle
                         {0, 0, 0.9f}, {1, 0, 0.9f}, {0, 1, 0.9f}};  // above
  triangles.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  scene::Layer balls;
  balls.primitive = scene::Primitive::balls;
  balls.positions = {{0.5f, 0.5f, 0.9f}, {0.5f, 0.5f, 0.2f}};
  balls.radii = {1, 2};
  scene.layers = {triangles, balls};
  scene::clip(scene, {0.5f, 0.0f, 90.0f});
  ASSERT_EQ(scene.layers[0].positions.size(), 3u);
  EXPECT_EQ(scene.layers[0].normals.size(), 3u);
  EXPECT_EQ(scene.layers[0].normals[0][2], 1.0f);
  ASSERT_EQ(scene.layers[1].radii.size(), 1u);
  EXPECT_EQ(scene.layers[1].radii[0], 2.0f);
}

}  // namespace
}  // namespace sculpt
