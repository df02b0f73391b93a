// SPDX-License-Identifier: GPL-3.0-or-later
// The sculpting replayed (scene/carving_replay.hpp): the hull's cells leave step by step, each
// for the method's own reason, and the replay ends exactly at the solid.
#include "scene/carving_replay.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "frontend/shots.hpp"
#include "scene/scene.hpp"
#include "scene/simplex_geometry.hpp"
#include "scene_layers.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

template <int D>
Reconstruction<D> reconstructed(const std::vector<Point<D>>& samples, Method method) {
  Options options;
  options.method = method;
  options.keep_triangulations = true;
  return reconstruct(samples, options);
}

const Reconstruction<2>& star(Method method) {
  static std::map<Method, Reconstruction<2>> results;
  auto found = results.find(method);
  if (found == results.end())
    found = results.emplace(method, reconstructed<2>(shapes::star(200).samples, method)).first;
  return found->second;
}

const Reconstruction<3>& torus(Method method) {
  static std::map<Method, Reconstruction<3>> results;
  auto found = results.find(method);
  if (found == results.end())
    found = results.emplace(method, reconstructed<3>(shapes::torus(1500, 1.0, 0.35), method)).first;
  return found->second;
}

template <int D>
std::set<Cell<D>> sorted_set(const std::vector<Cell<D>>& cells) {
  std::set<Cell<D>> result;
  for (auto cell : cells) {
    std::sort(cell.begin(), cell.end());
    result.insert(cell);
  }
  return result;
}

// What is left after every step is exactly the solid, and no cell leaves twice.
template <int D>
void ends_at_the_solid(const Reconstruction<D>& r) {
  const scene::Carving_replay replay = scene::carving_replay(r);
  ASSERT_FALSE(replay.steps.empty());
  std::set<int> left(replay.hull.begin(), replay.hull.end());
  for (const auto& step : replay.steps) {
    ASSERT_FALSE(step.cells.empty());
    for (int c : step.cells) ASSERT_EQ(left.erase(c), 1u) << "cell " << c << " left twice";
  }
  std::vector<Cell<D>> kept;
  for (int c : left) kept.push_back(r.delaunay.cells[c]);
  EXPECT_EQ(sorted_set<D>(kept), sorted_set<D>(r.solid));
}

TEST(CarvingReplay, EveryMethodEndsAtItsSolid2d) {
  for (Method m : {Method::paper, Method::robust, Method::boissonnat}) {
    SCOPED_TRACE(to_string(m));
    ends_at_the_solid(star(m));
  }
}

TEST(CarvingReplay, EveryMethodEndsAtItsSolid3d) {
  for (Method m : {Method::paper, Method::robust, Method::boissonnat}) {
    SCOPED_TRACE(to_string(m));
    ends_at_the_solid(torus(m));
  }
}

// Paper, sec. 3.3: a step's cells are those whose circumballs hold the pole it inserts, and
// none of them held a pole inserted before.
template <int D>
void poles_destroy_what_their_balls_hold(const Reconstruction<D>& r) {
  const scene::Carving_replay replay = scene::carving_replay(r);
  ASSERT_TRUE(replay.by_poles);
  const auto& inserted = r.insertion.inserted_poles;
  long previous = -1;
  for (const auto& step : replay.steps) {
    ASSERT_GE(step.pole, 0) << "no tie on a circumsphere in this input";
    const long order = std::find(inserted.begin(), inserted.end(), step.pole) - inserted.begin();
    ASSERT_LT(order, long(inserted.size()));
    EXPECT_GT(order, previous) << "poles go in the order of the list";
    previous = order;
    for (int c : step.cells) {
      std::array<Point<D>, D + 1> corners;
      for (int i = 0; i <= D; ++i) corners[i] = r.sites[r.delaunay.cells[c][i]];
      const Point<D> centre = scene::circumcenter<D>(corners);
      const auto distance = [&](const Point<D>& p) {
        double d = 0;
        for (int k = 0; k < D; ++k) d += (p[k] - centre[k]) * (p[k] - centre[k]);
        return std::sqrt(d);
      };
      const double radius = distance(corners[0]);
      EXPECT_LT(distance(r.poles.poles[step.pole].center), radius);
      for (long earlier = 0; earlier < order; ++earlier)
        EXPECT_GE(distance(r.poles.poles[inserted[earlier]].center), radius * (1 - 1e-9));
    }
  }
}

TEST(CarvingReplay, ThePapersPolesDestroyTheCellsTheirBallsHold) {
  poles_destroy_what_their_balls_hold(star(Method::paper));
  poles_destroy_what_their_balls_hold(torus(Method::paper));
}

// The robust method and Boissonnat's: one cell a step, in the order and for the reason recorded.
TEST(CarvingReplay, CarvingMethodsTakeOneCellAStepInTheirOrder) {
  for (Method m : {Method::robust, Method::boissonnat}) {
    SCOPED_TRACE(to_string(m));
    const auto& r = torus(m);
    const scene::Carving_replay replay = scene::carving_replay(r);
    EXPECT_FALSE(replay.by_poles);
    ASSERT_EQ(replay.steps.size(), r.carving.events.size());
    for (std::size_t i = 0; i < replay.steps.size(); ++i) {
      ASSERT_EQ(replay.steps[i].cells.size(), 1u);
      EXPECT_EQ(replay.steps[i].cells[0], r.carving.events[i].cell);
      EXPECT_EQ(replay.steps[i].reason, r.carving.events[i].reason);
    }
    EXPECT_EQ(scene::replay_length(r, scene::Stage::carving), long(replay.steps.size()));
  }
}

TEST(CarvingReplay, OnlyTheSculptingMethodsHaveTheStage) {
  for (Method m : {Method::paper, Method::robust, Method::boissonnat})
    EXPECT_TRUE(scene::has_stage(m, 3, scene::Stage::carving)) << to_string(m);
  for (Method m : {Method::crust, Method::cocone, Method::alpha_shape, Method::tight_cocone,
                   Method::advancing_front, Method::power_crust})
    EXPECT_FALSE(scene::has_stage(m, 3, scene::Stage::carving)) << to_string(m);
  EXPECT_TRUE(scene::replays(scene::Stage::carving));
  EXPECT_FALSE(scene::replays(scene::Stage::solid));
}

const scene::Layer* find(const scene::Scene& scene, const std::string& id) {
  return testing::find_layer(scene, id);
}

std::size_t primitives(const scene::Scene& scene, const std::string& id, std::size_t per) {
  const scene::Layer* layer = find(scene, id);
  return layer ? layer->positions.size() / per : 0;
}

// The 2D picture at a step: the cells left, those taken before, the step's own with their
// circumcircles, and (paper) the pole just inserted; counts that add up to the hull.
TEST(CarvingReplay, ThePictureAtAStepShowsWhatLeftAndWhen2d) {
  const auto& r = star(Method::paper);
  const scene::Carving_replay replay = scene::carving_replay(r);
  ASSERT_GE(replay.steps.size(), 5u);
  scene::Request request;
  request.stage = scene::Stage::carving;
  request.step = 0;
  const scene::Scene start = scene::build_scene(r, request);
  EXPECT_EQ(primitives(start, "solid", 3), replay.hull.size());
  EXPECT_EQ(find(start, "sculpted-away"), nullptr);
  EXPECT_EQ(find(start, "just-removed"), nullptr);

  request.step = 5;
  const scene::Scene fifth = scene::build_scene(r, request);
  std::size_t before = 0;
  for (int i = 0; i < 4; ++i) before += replay.steps[i].cells.size();
  const std::size_t now = replay.steps[4].cells.size();
  EXPECT_EQ(primitives(fifth, "sculpted-away", 3), before);
  EXPECT_EQ(primitives(fifth, "just-removed", 3), now);
  EXPECT_EQ(primitives(fifth, "solid", 3), replay.hull.size() - before - now);
  EXPECT_EQ(primitives(fifth, "just-removed-circles", 1), now);
  ASSERT_NE(find(fifth, "current-pole"), nullptr);
  EXPECT_NE(fifth.title.find("step 5 of " + std::to_string(replay.steps.size())), std::string::npos)
      << fifth.title;

  request.step = -1;  // all: the solid
  EXPECT_EQ(primitives(scene::build_scene(r, request), "solid", 3), r.solid.size());
}

// In 3D, uncut, the cells left are seen whole: at the end, their faces are the closed surface.
TEST(CarvingReplay, TheHullShrinksToTheSurface3d) {
  const auto& r = torus(Method::robust);
  scene::Request request;
  request.stage = scene::Stage::carving;
  request.step = 0;
  const std::size_t hull_faces = primitives(scene::build_scene(r, request), "solid", 3);
  request.step = -1;
  const scene::Scene end = scene::build_scene(r, request);
  EXPECT_EQ(primitives(end, "solid", 3), r.surface.size());
  EXPECT_NE(primitives(end, "solid", 3), hull_faces);
  EXPECT_NE(end.title.find("seen whole"), std::string::npos) << end.title;
  // In section, the step's cells are a fill of their own.
  request.step = scene::replay_length(r, scene::Stage::carving) / 2;
  request.sectioned = true;
  request.clip = scene::Clip{0.5f, 0, 0, 0};
  const scene::Scene section = scene::build_scene(r, request);
  EXPECT_GT(primitives(section, "section-inside", 3), 0u);
  EXPECT_GT(primitives(section, "section-away", 3), 0u);
}

// The co-cone's pruning replays triangle by triangle: at step k the first k pruned are gone,
// the k-th lit.
TEST(CarvingReplay, ThePruningReplaysTriangleByTriangle) {
  const auto& r = torus(Method::cocone);
  const long pruned = scene::replay_length(r, scene::Stage::candidates);
  ASSERT_EQ(pruned, long(r.candidates.pruned.size()));
  ASSERT_GE(pruned, 1);
  scene::Request request;
  request.stage = scene::Stage::candidates;
  request.step = 0;
  const scene::Scene start = scene::build_scene(r, request);
  EXPECT_EQ(primitives(start, "candidates", 3), r.candidates.chosen.size());
  EXPECT_EQ(find(start, "pruned"), nullptr);
  request.step = 1;
  const scene::Scene first = scene::build_scene(r, request);
  EXPECT_EQ(primitives(first, "candidates", 3), r.candidates.chosen.size() - 1);
  EXPECT_EQ(primitives(first, "just-removed", 3), 1u);
  EXPECT_EQ(primitives(first, "pruned", 6), 1u);  // its three sides
  request.step = -1;
  EXPECT_EQ(find(scene::build_scene(r, request), "just-removed"), nullptr);
}

// An animation of the carving replays it from the start to the end, frame by frame.
TEST(CarvingReplay, AnAnimationOfTheCarvingStepsThroughIt) {
  frontend::Shot shot;
  shot.animate = "replay";
  shot.stage = "carving";
  shot.frames = 6;
  const frontend::Any_reconstruction shown = star(Method::boissonnat);
  const auto frames = frontend::animation_frames(shot, shown);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(frames.front().step, 0);
  EXPECT_EQ(frames.back().step,
            scene::replay_length(star(Method::boissonnat), scene::Stage::carving));
  for (const auto& frame : frames) EXPECT_EQ(frame.stage, "carving");
  shot.stage = "surface";  // not a replay: the labelling's, which Boissonnat's method has not
  EXPECT_THROW(frontend::animation_frames(shot, shown), std::exception);
  const frontend::Any_reconstruction paper = star(Method::paper);
  EXPECT_EQ(frontend::animation_frames(shot, paper).front().stage, "propagation");
  const frontend::Any_reconstruction crust =
      reconstructed<2>(shapes::star(60).samples, Method::crust);
  shot.stage = "carving";
  EXPECT_THROW(frontend::animation_frames(shot, crust), std::exception);
}

}  // namespace
}  // namespace sculpt
