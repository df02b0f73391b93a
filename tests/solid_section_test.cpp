// SPDX-License-Identifier: GPL-3.0-or-later
// The 3D solid seen whole or cut through whole cells (never shrunk, never a half dropped
// unsaid), and the polar balls inner and outer apart, limited and translucent as asked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "scene/cut_cells.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

const scene::Layer* find(const scene::Scene& scene, const std::string& id) {
  for (const auto& layer : scene.layers) {
    if (layer.id == id) return &layer;
  }
  return nullptr;
}

const Reconstruction<3>& bumpy() {
  static const auto result = reconstruct(shapes::bumpy_sphere(1500));
  return result;
}

// Two tetrahedra sharing the face {1, 2, 3}.
const std::vector<scene::Tetrahedron> two_cells{{0, 1, 2, 3}, {4, 1, 2, 3}};

TEST(CutCells, BothKeptShowTheirSixOuterFaces) {
  const auto shown = scene::shown_faces(two_cells, {true, true});
  EXPECT_EQ(shown.faces.size(), 6u);
  EXPECT_TRUE(shown.on_cut.empty());
  for (const auto& face : shown.faces) {
    auto sorted = face;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_NE(sorted, (scene::Face{1, 2, 3})) << "the shared face is inside";
  }
}

TEST(CutCells, OneCutAwayLeavesTheOtherWholeWithTheSharedFaceOnTheCut) {
  const auto shown = scene::shown_faces(two_cells, {true, false});
  ASSERT_EQ(shown.faces.size(), 4u);
  ASSERT_EQ(shown.on_cut.size(), 1u);
  auto cut = shown.on_cut[0];
  std::sort(cut.begin(), cut.end());
  EXPECT_EQ(cut, (scene::Face{1, 2, 3}));
  for (const auto& face : shown.faces) EXPECT_EQ(std::count(face.begin(), face.end(), 4), 0);
}

TEST(CutCells, FacesDrawnElsewhereAreLeftOut) {
  const auto elsewhere = scene::sorted_faces({{3, 2, 1}, {0, 2, 1}});
  const auto shown = scene::shown_faces(two_cells, {true, false}, elsewhere);
  EXPECT_EQ(shown.faces.size(), 2u);
  EXPECT_TRUE(shown.on_cut.empty());
}

// Every corner of the solid's triangles is a sample: the cells are drawn whole, not shrunk.
TEST(SolidSection, TheCellsAreWholeAndTheCutIsSaid) {
  scene::Request request;
  request.stage = scene::Stage::solid;
  const auto scene = scene::build_scene(bumpy(), request);
  const scene::Layer* solid = find(scene, "solid");
  ASSERT_NE(solid, nullptr);
  ASSERT_GT(solid->positions.size(), 0u);
  std::vector<std::array<float, 3>> samples;
  for (const auto& s : bumpy().sites) samples.push_back({float(s[0]), float(s[1]), float(s[2])});
  std::sort(samples.begin(), samples.end());
  for (const auto& p : solid->positions)
    EXPECT_TRUE(std::binary_search(samples.begin(), samples.end(), p));
  EXPECT_NE(scene.title.find("cut away"), std::string::npos) << scene.title;
  request.clipped = true;
  EXPECT_NE(scene::build_scene(bumpy(), request).title.find("clip plane"), std::string::npos);
}

// With nothing cut (the plane beyond the box), the solid shows exactly its boundary: every
// edge on two triangles, as many triangles as the closed surface has.
TEST(SolidSection, UncutTheSolidIsItsClosedBoundary) {
  scene::Request request;
  request.stage = scene::Stage::solid;
  request.clipped = true;
  request.clip.position = 1;
  const auto scene = scene::build_scene(bumpy(), request);
  const scene::Layer* solid = find(scene, "solid");
  ASSERT_NE(solid, nullptr);
  EXPECT_EQ(solid->positions.size() / 3, bumpy().surface.size());
  std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> edges;
  for (std::size_t t = 0; t < solid->positions.size(); t += 3) {
    for (int i = 0; i < 3; ++i)
      ++edges[std::minmax(solid->positions[t + i], solid->positions[t + (i + 1) % 3])];
  }
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);
}

// The user's clip moves the cut: the cells kept are those whose centre lies before the plane,
// each whole, so the corners reach past the plane by at most a cell and the shares differ.
TEST(SolidSection, TheUsersClipMovesTheCut) {
  scene::Request request;
  request.stage = scene::Stage::solid;
  request.clipped = true;
  request.clip.elevation = 90;  // across z
  std::size_t previous = 0;
  for (float position : {0.25f, 0.5f, 0.75f}) {
    request.clip.position = position;
    const auto scene = scene::build_scene(bumpy(), request);
    const scene::Layer* solid = find(scene, "solid");
    ASSERT_NE(solid, nullptr);
    float lowest = INFINITY;
    for (const auto& p : solid->positions) lowest = std::min(lowest, p[2]);
    EXPECT_NEAR(lowest, scene.lower[2], 1e-6f);  // the lower part is all there
    const std::size_t cut =
        find(scene, "cut-cells") ? find(scene, "cut-cells")->positions.size() : 0;
    EXPECT_GT(cut, 0u) << "the section's cells show their edges";
    EXPECT_NE(solid->positions.size(), previous);
    previous = solid->positions.size();
    // What was sculpted away is cut at the same plane and never drawn over the solid's faces.
    const scene::Layer* away = find(scene, "sculpted-away");
    ASSERT_NE(away, nullptr);
    EXPECT_TRUE(away->cut && solid->cut);
  }
}

// Inner and outer balls are layers apart, by the labels the stage knows, each at most the
// limit, with the opacity asked for (the outer ones fainter).
TEST(PolarBalls, InnerAndOuterApartLimitedAndTranslucent) {
  scene::Request request;
  request.stage = scene::Stage::poles;
  request.polar_balls = true;
  request.ball_limit = 25;
  request.ball_opacity = 0.6f;
  const auto scene = scene::build_scene(bumpy(), request);
  const scene::Layer* inner = find(scene, "inner-balls");
  const scene::Layer* outer = find(scene, "outer-balls");
  ASSERT_NE(inner, nullptr);
  ASSERT_NE(outer, nullptr);
  EXPECT_EQ(inner->radii.size(), 25u);
  EXPECT_LE(outer->radii.size(), 25u);
  EXPECT_GT(outer->radii.size(), 0u);
  EXPECT_FLOAT_EQ(inner->color.a, 0.6f);
  EXPECT_LT(outer->color.a, inner->color.a);
  EXPECT_NE(inner->label.find("of"), std::string::npos) << "the label says how many are shown";
  // The inner balls of a sphere lie inside it: their centres within its radius.
  for (const auto& c : inner->positions) EXPECT_LT(std::hypot(c[0], c[1], c[2]), 1.2f);

  // Before the first labelling event of the replay, no ball is labelled yet.
  request.stage = scene::Stage::propagation;
  request.step = 0;
  const auto before = scene::build_scene(bumpy(), request);
  EXPECT_TRUE(find(before, "inner-balls")->radii.empty());
  EXPECT_TRUE(find(before, "outer-balls")->radii.empty());
  ASSERT_NE(find(before, "polar-balls"), nullptr);
  EXPECT_NE(find(before, "polar-balls")->label.find("not yet labelled"), std::string::npos);
}

}  // namespace
}  // namespace sculpt
