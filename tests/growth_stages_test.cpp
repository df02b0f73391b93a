// SPDX-License-Identifier: GPL-3.0-or-later
// The peers that grow a shape, stepped (scene/growth_stages.hpp): the Advancing Front's
// triangles in the order CGAL added them, and the alpha shape's cells as alpha grows.
#include "scene/growth_stages.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "scene/carving_replay.hpp"
#include "scene/scene.hpp"
#include "scene_layers.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

const Reconstruction<3>& torus(Method method) {
  static std::map<Method, Reconstruction<3>> results;
  auto found = results.find(method);
  if (found == results.end()) {
    Options options;
    options.method = method;
    options.keep_triangulations = true;
    found = results.emplace(method, reconstruct(shapes::torus(1500, 1.0, 0.35), options)).first;
  }
  return found->second;
}

std::set<std::array<int, 3>> unoriented(const std::vector<Facet<3>>& triangles) {
  std::set<std::array<int, 3>> result;
  for (auto t : triangles) {
    std::sort(t.begin(), t.end());
    result.insert(t);
  }
  return result;
}

const scene::Layer* find(const scene::Scene& scene, const std::string& id) {
  return testing::find_layer(scene, id);
}

std::size_t count(const scene::Scene& scene, const std::string& id, std::size_t per) {
  const scene::Layer* layer = find(scene, id);
  return layer ? layer->positions.size() / per : 0;
}

scene::Scene at_step(const Reconstruction<3>& r, scene::Stage stage, long step) {
  scene::Request request;
  request.stage = stage;
  request.step = step;
  return scene::build_scene(r, request);
}

TEST(GrowthStages, AreThePeersOwnReplays) {
  EXPECT_TRUE(scene::has_stage(Method::advancing_front, 3, scene::Stage::front));
  EXPECT_TRUE(scene::has_stage(Method::alpha_shape, 3, scene::Stage::alpha));
  EXPECT_FALSE(scene::has_stage(Method::robust, 3, scene::Stage::front));
  EXPECT_FALSE(scene::has_stage(Method::advancing_front, 3, scene::Stage::alpha));
  EXPECT_TRUE(scene::replays(scene::Stage::front));
  EXPECT_TRUE(scene::replays(scene::Stage::alpha));
  scene::Stage parsed;
  ASSERT_TRUE(scene::parse_stage("front", parsed));
  EXPECT_EQ(parsed, scene::Stage::front);
}

// The order is a permutation of the surface, which is CGAL's own surface; the front grows: after
// the seed, almost every triangle is added on an edge of those before it (a new seed starts
// only where the front closed or stopped).
TEST(GrowthStages, TheFrontAddsItsTrianglesOnItsBorder) {
  const auto& r = torus(Method::advancing_front);
  const auto& order = r.front.order;
  ASSERT_EQ(order.size(), r.surface.size());
  ASSERT_GT(order.size(), 2000u);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], int(i));

  const std::vector<Point<3>> samples(r.sites.begin(), r.sites.begin() + long(r.sample_count()));
  EXPECT_EQ(unoriented(r.surface), unoriented(cgal_advancing_front(samples)));

  std::set<std::array<int, 2>> edges;
  std::size_t apart = 0;
  for (int index : order) {
    const Facet<3>& t = r.surface[index];
    bool touches = false;
    std::array<std::array<int, 2>, 3> own;
    for (int j = 0; j < 3; ++j) {
      own[j] = {std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3])};
      touches = touches || edges.count(own[j]);
    }
    apart += !touches;
    edges.insert(own.begin(), own.end());
  }
  EXPECT_GE(apart, 1u);
  EXPECT_LE(apart * 100, order.size()) << apart << " triangles started apart";
  EXPECT_EQ(scene::replay_length(r, scene::Stage::front), long(order.size()));
}

// The picture at a step: the triangles before it, its own lit, the front closing the border.
TEST(GrowthStages, TheFrontsPictureCountsUp) {
  const auto& r = torus(Method::advancing_front);
  const auto before = at_step(r, scene::Stage::front, 0);
  EXPECT_EQ(count(before, "just-added", 3), 0u);
  EXPECT_EQ(count(before, "samples", 1), r.sample_count());
  const auto first = at_step(r, scene::Stage::front, 1);
  EXPECT_EQ(count(first, "just-added", 3), 1u);
  EXPECT_EQ(count(first, "front", 2), 3u);
  EXPECT_EQ(count(first, "samples", 1), r.sample_count() - 3);
  const auto middle = at_step(r, scene::Stage::front, 500);
  EXPECT_EQ(count(middle, "surface", 3), 499u);
  EXPECT_EQ(count(middle, "just-added", 3), 1u);
  EXPECT_GT(count(middle, "front", 2), 10u);
  EXPECT_NE(middle.title.find("triangle 500 of"), std::string::npos) << middle.title;
  // The torus closes: at the end the front is gone and every sample reached.
  const auto all = at_step(r, scene::Stage::front, -1);
  EXPECT_EQ(count(all, "front", 2), 0u);
  EXPECT_EQ(count(all, "samples", 1), 0u);
}

// The filtration: every cell of the samples' Delaunay triangulation once, smallest circumball
// first; the method's solid is exactly its first `chosen` cells.
TEST(GrowthStages, TheAlphaShapesCellsJoinSmallestFirst) {
  const auto& r = torus(Method::alpha_shape);
  const Alpha_stage& alpha = r.alpha;
  ASSERT_EQ(alpha.cells.size(), alpha.radii.size());
  ASSERT_GT(alpha.cells.size(), 5000u);
  EXPECT_TRUE(std::is_sorted(alpha.radii.begin(), alpha.radii.end()));
  std::set<std::array<int, 4>> distinct;
  for (auto cell : alpha.cells) {
    std::sort(cell.begin(), cell.end());
    EXPECT_TRUE(distinct.insert(cell).second);
  }
  ASSERT_GT(alpha.chosen, 0u);
  ASSERT_LT(alpha.chosen, alpha.cells.size());
  EXPECT_NEAR(alpha.radii[alpha.chosen - 1], r.stats.alpha, 1e-9 * r.stats.alpha);
  EXPECT_LT(alpha.radii[alpha.chosen - 1], alpha.radii[alpha.chosen]);
  const auto sorted = [](std::vector<Cell<3>> cells) {
    for (auto& cell : cells) std::sort(cell.begin(), cell.end());
    std::sort(cells.begin(), cells.end());
    return cells;
  };
  EXPECT_EQ(sorted({alpha.cells.begin(), alpha.cells.begin() + long(alpha.chosen)}),
            sorted(r.solid));
  EXPECT_EQ(scene::replay_length(r, scene::Stage::alpha), long(alpha.cells.size()));
}

// Its picture: the samples alone at alpha 0, the method's solid when no step is asked for, and
// the hull at the end with every sample on a cell.
TEST(GrowthStages, TheAlphaPictureGrowsFromTheSamplesToTheHull) {
  const auto& r = torus(Method::alpha_shape);
  const auto none = at_step(r, scene::Stage::alpha, 0);
  EXPECT_EQ(count(none, "samples", 1), r.sample_count());
  EXPECT_EQ(count(none, "solid", 3), 0u);
  const auto own = at_step(r, scene::Stage::alpha, -1);
  EXPECT_NE(own.title.find("the method's alpha"), std::string::npos) << own.title;
  EXPECT_EQ(count(own, "samples", 1), 0u);
  // The method's solid is the torus: its faces are the surface's triangles.
  EXPECT_EQ(count(own, "solid", 3), r.surface.size());
  EXPECT_EQ(count(own, "just-added", 3), 0u);
  const auto early = at_step(r, scene::Stage::alpha, long(r.alpha.chosen / 4));
  EXPECT_EQ(count(early, "just-added", 3), 4u);
  EXPECT_GT(count(early, "samples", 1), 0u);
  const auto hull = at_step(r, scene::Stage::alpha, long(r.alpha.cells.size()));
  // The hull of a torus covers its hole: fewer faces show than at the method's alpha.
  EXPECT_GT(count(hull, "solid", 3), 0u);
  EXPECT_LT(count(hull, "solid", 3), count(own, "solid", 3));
}

}  // namespace
}  // namespace sculpt
