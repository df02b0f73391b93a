// SPDX-License-Identifier: GPL-3.0-or-later
// A true section of a 3D stage: the cells a plane cuts as the polygons of the cut, filled by
// what they are; the surface and the Voronoi faces where the plane crosses them; the samples
// near it. Checked against a torus whose section is known: two discs of the tube's radius.
#include "scene/section.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "frontend/shots.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

const scene::Layer* find(const scene::Scene& scene, const std::string& id) {
  for (const auto& layer : scene.layers) {
    if (layer.id == id) return &layer;
  }
  return nullptr;
}

scene::Clip_plane plane_z(float offset) {
  scene::Clip_plane plane;
  plane.normal = {0, 0, 1};
  plane.offset = offset;
  return plane;
}

float area(const std::vector<scene::Vec3>& triangles) {
  float total = 0;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const auto &a = triangles[t], &b = triangles[t + 1], &c = triangles[t + 2];
    const scene::Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const scene::Vec3 v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    total += 0.5f * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                               u[0] * v[1] - u[1] * v[0]);
  }
  return total;
}

const std::array<scene::Vec3, 4> unit_tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

TEST(CutTetrahedron, OneCornerBeyondGivesATriangle) {
  std::vector<scene::Vec3> fill, outline;
  scene::cut_tetrahedron(unit_tetrahedron, plane_z(0.5f), fill, outline);
  ASSERT_EQ(fill.size(), 3u);
  EXPECT_EQ(outline.size(), 6u);
  for (const auto& p : fill) EXPECT_FLOAT_EQ(p[2], 0.5f);
  EXPECT_NEAR(area(fill), 0.125f, 1e-6f);  // the corner triangle of side 0.5
}

TEST(CutTetrahedron, TwoCornersEachSideGiveAQuadrilateral) {
  scene::Clip_plane plane;
  plane.normal = {float(M_SQRT1_2), float(M_SQRT1_2), 0};  // x + y = 0.5 sqrt 2 ... scaled
  plane.offset = 0.5f * float(M_SQRT1_2);                  // x + y = 0.5
  std::vector<scene::Vec3> fill, outline;
  // Corners (1,0,0) and (0,1,0) beyond, (0,0,0) and (0,0,1) before.
  scene::cut_tetrahedron(unit_tetrahedron, plane, fill, outline);
  EXPECT_EQ(fill.size(), 6u);     // two triangles
  EXPECT_EQ(outline.size(), 8u);  // four sides
  for (const auto& p : fill) EXPECT_NEAR(plane.side(p), 0.0f, 1e-6f);
  EXPECT_GT(area(fill), 0.0f);
}

TEST(CutTetrahedron, APlaneThatMissesCutsNothing) {
  std::vector<scene::Vec3> fill, outline;
  scene::cut_tetrahedron(unit_tetrahedron, plane_z(2.0f), fill, outline);
  scene::cut_tetrahedron(unit_tetrahedron, plane_z(-1.0f), fill, outline);
  EXPECT_TRUE(fill.empty());
  EXPECT_TRUE(outline.empty());
}

constexpr double tube = 0.3;

const Reconstruction<3>& torus() {
  static const auto result = [] {
    Options options;
    options.keep_triangulations = true;
    return reconstruct(shapes::torus(6000, 1.0, tube), options);
  }();
  return result;
}

// The plane x = 0 (the middle across x, normal +x) cuts the torus's tube in two discs.
scene::Request section_across_x(scene::Stage stage) {
  scene::Request request;
  request.stage = stage;
  request.sectioned = true;
  request.clip.position = 0.5f;
  return request;
}

TEST(Section, TheSolidCutIsTheTubesTwoDiscs) {
  const auto scene = scene::build_section(torus(), section_across_x(scene::Stage::solid));
  ASSERT_TRUE(scene.seen_along);
  EXPECT_NEAR(scene.along[0], 1.0f, 1e-6f);
  const scene::Layer* inside = find(scene, "section-inside");
  const scene::Layer* away = find(scene, "section-away");
  ASSERT_NE(inside, nullptr);
  ASSERT_NE(away, nullptr);
  for (const auto& p : inside->positions) EXPECT_NEAR(p[0], 0.0f, 1e-3f);
  // Inscribed polygons of the discs: a little less than 2 pi r^2, never more.
  const float discs = float(2 * M_PI * tube * tube);
  EXPECT_GT(area(inside->positions), 0.93f * discs);
  EXPECT_LT(area(inside->positions), 1.01f * discs);
  // What was sculpted away fills the hull's section around them.
  EXPECT_GT(area(away->positions), discs);
  const scene::Layer* samples = find(scene, "samples");
  ASSERT_NE(samples, nullptr);
  EXPECT_GT(samples->positions.size(), 20u);
  // Each sample near the plane lies on the tube's circles: |(y, z) - (±1, 0)| = r.
  for (const auto& p : samples->positions)
    EXPECT_NEAR(std::hypot(std::abs(p[1]) - 1.0f, p[2]), float(tube), 0.03f);
}

TEST(Section, TheSurfaceCutIsTheTwoCircles) {
  const auto scene = scene::build_section(torus(), section_across_x(scene::Stage::surface));
  const scene::Layer* curve = find(scene, "surface-section");
  ASSERT_NE(curve, nullptr);
  float length = 0;
  for (std::size_t s = 0; s + 1 < curve->positions.size(); s += 2) {
    const auto &a = curve->positions[s], &b = curve->positions[s + 1];
    length += std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  }
  const float circles = float(4 * M_PI * tube);
  EXPECT_GT(length, 0.97f * circles);
  EXPECT_LT(length, 1.01f * circles);
}

TEST(Section, TheVoronoiFacesCutAreSegmentsInThePlane) {
  const auto scene = scene::build_section(torus(), section_across_x(scene::Stage::voronoi));
  const scene::Layer* faces = find(scene, "voronoi-section");
  ASSERT_NE(faces, nullptr);
  EXPECT_GT(faces->positions.size(), 100u);
  for (const auto& p : faces->positions) EXPECT_NEAR(p[0], 0.0f, 1e-2f);
}

TEST(Section, ThePaperMethodsSculptedTriangulationShowsWhatItsPolesTookAway) {
  Options paper;
  paper.method = Method::paper;
  paper.keep_triangulations = true;
  const auto r = reconstruct(shapes::torus(3000, 1.0, tube), paper);
  const auto scene = scene::build_section(r, section_across_x(scene::Stage::sculpted_delaunay));
  ASSERT_NE(find(scene, "section-inside"), nullptr);
  ASSERT_NE(find(scene, "section-away"), nullptr);
  ASSERT_NE(find(scene, "outer-poles"), nullptr);
  EXPECT_GT(find(scene, "outer-poles")->positions.size(), 0u);
}

// A stage sweep draws the stages that would be one colour (a 3D triangulation's or diagram's
// edges) in section, at a plane facing the camera; the others as they are.
TEST(Section, AStageSweepSectionsTheStagesThatFillSpace) {
  frontend::Shot shot;
  shot.animate = "stages";
  const frontend::Any_reconstruction r = torus();
  int sectioned = 0;
  for (const auto& frame : frontend::animation_frames(shot, r)) {
    scene::Stage stage;
    ASSERT_TRUE(scene::parse_stage(frame.stage, stage));
    const bool fills_space = stage == scene::Stage::delaunay || stage == scene::Stage::voronoi ||
                             stage == scene::Stage::sculpted_delaunay;
    EXPECT_EQ(!frame.section.empty(), fills_space) << frame.stage;
    if (frame.section.empty()) continue;
    ++sectioned;
    const auto scene = frontend::scene_of(frame, r);
    // The plane faces the camera: its normal is the direction the camera looks from.
    const float yaw = float(shot.yaw), pitch = float(shot.pitch);
    EXPECT_NEAR(scene.along[0], std::cos(pitch) * std::sin(yaw), 1e-4f);
    EXPECT_NEAR(scene.along[1], std::sin(pitch), 1e-4f);
    EXPECT_NEAR(scene.along[2], std::cos(pitch) * std::cos(yaw), 1e-4f);
  }
  EXPECT_EQ(sectioned, 3);
  // A sweep the user cuts is left as asked.
  shot.clip = "0.5,0,90";
  for (const auto& frame : frontend::animation_frames(shot, r)) EXPECT_TRUE(frame.section.empty());
}

}  // namespace
}  // namespace sculpt
