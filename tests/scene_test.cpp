// SPDX-License-Identifier: GPL-3.0-or-later
// The scene layer without GL: which layers each stage has, the propagation replay, the camera.
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/camera.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

const Reconstruction<2>& star() {
  static const auto result = [] {
    Options paper;
    paper.method = Method::paper;
    return reconstruct(shapes::star(80).samples, paper);
  }();
  return result;
}

const scene::Layer* find(const scene::Scene& scene, const std::string& id) {
  for (const auto& layer : scene.layers) {
    if (layer.id == id) return &layer;
  }
  return nullptr;
}

TEST(Scene, StagesHaveTheirLayers) {
  const std::pair<scene::Stage, std::vector<std::string>> expected[] = {
      {scene::Stage::samples, {"samples"}},
      {scene::Stage::delaunay, {"delaunay", "samples"}},
      {scene::Stage::hull, {"hull", "hull-edges", "samples"}},
      {scene::Stage::voronoi, {"voronoi", "samples"}},
      {scene::Stage::poles, {"polar-balls", "poles", "samples"}},
      {scene::Stage::seeds, {"other-poles", "inner-seeds", "outer-seeds", "samples"}},
      {scene::Stage::outer_concave, {"inner-poles", "outer-poles", "samples"}},
      {scene::Stage::sculpted_delaunay,
       {"sculpted-delaunay", "inner-poles", "outer-poles", "samples"}},
      {scene::Stage::solid, {"solid", "sculpted-away", "samples"}},
      {scene::Stage::surface, {"curve", "samples"}},
  };
  for (const auto& [stage, ids] : expected) {
    scene::Request request;
    request.stage = stage;
    EXPECT_EQ(scene::layer_ids(scene::build_scene(star(), request)), ids) << scene::stage_id(stage);
  }
}

// Where a result ends and where it is not a manifold is drawn, not only counted: curve ends, a
// surface's border edges (two end points each) and its non-manifold edges.
// Samples in rings of `around` around a torus's tube (radius 0.11), each ring turned half a step.
std::vector<Point<3>> thin_torus(int around, int along = 40) {
  std::vector<Point<3>> samples;
  const double pi = std::acos(-1.0), tube = 0.11;
  for (int i = 0; i < along; ++i) {
    for (int j = 0; j < around; ++j) {
      const double theta = 2 * pi * i / along, phi = (2 * j + i % 2) * pi / around;
      const double r = 1 + tube * std::cos(phi);
      samples.push_back({r * std::cos(theta), r * std::sin(theta), tube * std::sin(phi)});
    }
  }
  return samples;
}

TEST(Scene, TheSurfaceStageDrawsTheLoopsOfThinHandles) {
  Options options;
  options.cleaning = Cleaning::none;
  const auto torus = reconstruct(thin_torus(4), options);
  ASSERT_EQ(torus.stats.thin_handles, 1u) << verdict(torus.stats).line;
  scene::Request surface;
  surface.stage = scene::Stage::surface;
  const scene::Scene scene = scene::build_scene(torus, surface);
  const scene::Layer* loops = find(scene, "thin-handles");
  ASSERT_NE(loops, nullptr);
  EXPECT_EQ(loops->positions.size(), 8u) << "four edges around the tube";
  EXPECT_EQ(loops->label, "suspect handles, thinner than the spacing (1)");
  EXPECT_EQ(find(scene::build_scene(reconstruct(thin_torus(5), options), surface), "thin-handles"),
            nullptr);
}

TEST(Scene, TheSurfaceStageShowsBordersAndDefects) {
  scene::Request surface;
  surface.stage = scene::Stage::surface;
  EXPECT_EQ(find(scene::build_scene(star(), surface), "border"), nullptr) << "a closed curve";

  Options bordered;
  bordered.kind = Surface_kind::bordered;
  const auto strokes = reconstruct(shapes::two_strokes().samples, bordered);
  const scene::Scene ends_scene = scene::build_scene(strokes, surface);
  const scene::Layer* ends = find(ends_scene, "border");
  ASSERT_NE(ends, nullptr);
  EXPECT_EQ(ends->positions.size(), 4u) << "two strokes, four ends";
  EXPECT_EQ(ends->label, "curve ends (4)");

  const auto saddle = reconstruct(shapes::saddle(20), bordered);
  const scene::Scene border_scene = scene::build_scene(saddle, surface);
  const scene::Layer* border = find(border_scene, "border");
  ASSERT_NE(border, nullptr);
  EXPECT_EQ(border->positions.size(), 2 * saddle.stats.boundary_ridges);

  Options closed;  // the saddle as if it were closed: the paper's rule leaves defects
  closed.method = Method::paper;
  closed.kind = Surface_kind::closed;
  const auto forced = reconstruct(shapes::saddle(20), closed);
  ASSERT_GT(forced.stats.non_manifold_ridges, 0u);
  const scene::Scene defects_scene = scene::build_scene(forced, surface);
  const scene::Layer* defects = find(defects_scene, "non-manifold");
  ASSERT_NE(defects, nullptr);
  EXPECT_EQ(defects->positions.size(), 2 * forced.stats.non_manifold_ridges);
}

TEST(Scene, TheSamplesStageShowsWhatTheCleaningDid) {
  // A noisy sphere and three strays far off it, cleaned of both: the samples as given (grey),
  // the strays removed (red), and a line from each sample kept to where smoothing moved it.
  const std::vector<Point<3>> sphere = shapes::noisy_sphere(2000, 0.4);
  std::vector<Point<3>> samples;  // the strays among the sphere's samples, before the k-th
  const std::vector<int> before = {3, 1000, 1500};
  for (int i = 0; i < 2000; ++i) {
    if (std::find(before.begin(), before.end(), i) != before.end())
      samples.push_back({1.5 + 0.1 * samples.size() / 1000, 0.1, 0.2});
    samples.push_back(sphere[i]);
  }
  Options options;
  options.cleaning = Cleaning::outliers_and_jet;
  const auto cleaned = reconstruct(samples, options);
  ASSERT_EQ(cleaned.removed_outliers, (std::vector<int>{3, 1001, 1502}));
  scene::Request request;
  request.stage = scene::Stage::samples;
  const scene::Scene scene = scene::build_scene(cleaned, request);
  ASSERT_NE(find(scene, "given-samples"), nullptr);
  EXPECT_EQ(find(scene, "given-samples")->positions.size(), 2003u);
  ASSERT_NE(find(scene, "outliers"), nullptr);
  ASSERT_EQ(find(scene, "outliers")->positions.size(), 3u);
  EXPECT_FLOAT_EQ(find(scene, "outliers")->positions[1][0], float(samples[1001][0]));
  const scene::Layer* moves = find(scene, "smoothing");
  ASSERT_NE(moves, nullptr);
  ASSERT_EQ(moves->positions.size(), 2 * 2000u);
  for (int s : {0, 3, 999, 1000, 1999}) {  // each line from a sample as given to where it went
    EXPECT_FLOAT_EQ(moves->positions[2 * s][0], float(sphere[s][0])) << s;
    EXPECT_FLOAT_EQ(moves->positions[2 * s + 1][0], float(cleaned.sites[s][0])) << s;
  }

  options.cleaning = Cleaning::outliers;  // removed, not smoothed: no lines
  EXPECT_EQ(find(scene::build_scene(reconstruct(samples, options), request), "smoothing"), nullptr);
}

TEST(Scene, PropagationReplaysEventByEvent) {
  scene::Request request;
  request.stage = scene::Stage::propagation;
  for (long step : {1L, 10L, 50L}) {
    request.step = step;
    const auto s = scene::build_scene(star(), request);
    std::size_t labelled =
        find(s, "inner-poles")->positions.size() + find(s, "outer-poles")->positions.size();
    EXPECT_EQ(labelled, std::size_t(step));
    const auto& event = star().propagation.events[step - 1];
    const auto& pole = star().poles.poles[event.pole].center;
    EXPECT_FLOAT_EQ(find(s, "current-pole")->positions[0][0], float(pole[0]));
    EXPECT_EQ(find(s, "source-ball") != nullptr, event.source >= 0);
  }
  request.step = -1;
  EXPECT_EQ(find(scene::build_scene(star(), request), "unlabelled-poles")->positions.size(),
            star().propagation.unlabelled);
}

TEST(Scene, LayerSelectionAndErrors) {
  scene::Request request;
  request.stage = scene::Stage::poles;
  request.layers = {"poles"};
  EXPECT_EQ(scene::layer_ids(scene::build_scene(star(), request)),
            std::vector<std::string>{"poles"});
  request.layers = {"nonsense"};
  EXPECT_THROW(scene::build_scene(star(), request), std::invalid_argument);
  request = {};
  request.focus_sample = 1000;
  EXPECT_THROW(scene::build_scene(star(), request), std::invalid_argument);

  Options lean;
  lean.keep_triangulations = false;
  const auto without_cells = reconstruct(shapes::star(40).samples, lean);
  request = {};
  request.stage = scene::Stage::delaunay;
  EXPECT_THROW(scene::build_scene(without_cells, request), std::invalid_argument);
}

// The solid stage shows what sculpting took away from the hull beside what it kept: together
// they are exactly the hull's cells (the all-sample cells of stage 1), in 2D and 3D.
TEST(Scene, TheSolidStageShowsTheCellsSculptedAway) {
  const auto hull_cells = [](const auto& r) {
    std::size_t count = 0;
    const int n = static_cast<int>(r.sample_count());
    for (const auto& cell : r.delaunay.cells) {
      count += std::all_of(cell.begin(), cell.end(), [&](int v) { return v < n; });
    }
    return count;
  };
  scene::Request request;
  request.stage = scene::Stage::solid;
  const scene::Scene curve = scene::build_scene(star(), request);
  const scene::Layer* away = find(curve, "sculpted-away");
  ASSERT_NE(away, nullptr);
  EXPECT_EQ(away->positions.size() / 3 + star().solid.size(), hull_cells(star()));
  EXPECT_GT(away->positions.size(), 0u);
  EXPECT_NE(away->label.find(std::to_string(away->positions.size() / 3)), std::string::npos);

  // In 3D (tetrahedra in the back half only, four triangles each): present, and labelled with
  // the count of every cell removed.
  const auto surface = reconstruct(shapes::bumpy_sphere(1500));
  const scene::Scene solid = scene::build_scene(surface, request);
  const scene::Layer* removed = find(solid, "sculpted-away");
  ASSERT_NE(removed, nullptr);
  EXPECT_GT(removed->positions.size(), 0u);
  EXPECT_NE(removed->label.find(std::to_string(hull_cells(surface) - surface.solid.size())),
            std::string::npos)
      << removed->label;
  // A method whose solid is not made of the hull's cells shows none.
  Options alpha;
  alpha.method = Method::alpha_shape;
  const auto shape = reconstruct(shapes::bumpy_sphere(1500), alpha);
  const scene::Scene alpha_solid = scene::build_scene(shape, request);
  EXPECT_EQ(find(alpha_solid, "sculpted-away"), nullptr);
}

// The samples a result leaves off are marked at the surface stage, one point each.
TEST(Scene, TheSurfaceStageMarksTheSamplesLeftOff) {
  Options tiny_alpha;
  tiny_alpha.method = Method::alpha_shape;
  tiny_alpha.alpha = 0.05;  // smaller than the spacing: many samples on no triangle
  const auto r = reconstruct(shapes::sphere(400), tiny_alpha);
  ASSERT_GT(r.stats.unused_samples, 0u);
  scene::Request request;
  const auto scene = scene::build_scene(r, request);
  const scene::Layer* unused = find(scene, "unused-samples");
  ASSERT_NE(unused, nullptr);
  EXPECT_EQ(unused->positions.size(), r.stats.unused_samples);
  // A result through every sample marks none.
  EXPECT_EQ(find(scene::build_scene(star(), request), "unused-samples"), nullptr);
}

TEST(Scene, FocusShowsTwoBallsAndTheirSquares) {
  scene::Request request;
  request.stage = scene::Stage::samples;
  request.focus_sample = 5;
  const auto s = scene::build_scene(star(), request);
  EXPECT_EQ(find(s, "focus-balls")->radii.size(), 2u);
  EXPECT_EQ(find(s, "focus-cubes")->positions.size(), 2u * 4u * 2u);  // 2 squares, 4 edges
}

// The neighbourhood view keeps what lies near the picked sample, and the picked sample's balls
// whole; the scene's bounds (what the camera fits) become the neighbourhood's.
TEST(Scene, TheNeighbourhoodViewKeepsWhatLiesNearThePickedSample) {
  Options options;
  options.keep_triangulations = true;
  // (Not a sphere: its samples are cospherical, their Voronoi vertices all at its centre.)
  const auto r = reconstruct(shapes::bumpy_sphere(1500), options);
  for (scene::Stage stage : {scene::Stage::delaunay, scene::Stage::voronoi}) {
    scene::Request whole;
    whole.stage = stage;
    whole.focus_sample = 5;
    scene::Request near = whole;
    near.neighbourhood = true;
    const auto all = scene::build_scene(r, whole), kept = scene::build_scene(r, near);
    const std::string edges = stage == scene::Stage::delaunay ? "delaunay" : "voronoi";
    ASSERT_NE(find(kept, edges), nullptr);
    EXPECT_LT(find(kept, edges)->positions.size() * 10, find(all, edges)->positions.size());
    EXPECT_GT(find(kept, edges)->positions.size(), 0u);
    EXPECT_EQ(find(kept, "focus-balls")->radii.size(), find(all, "focus-balls")->radii.size());
    const auto& s = r.sites[5];
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(kept.lower[c], s[c]);
      EXPECT_GE(kept.upper[c], s[c]);
      EXPECT_LT(kept.upper[c] - kept.lower[c], 0.5f * (all.upper[c] - all.lower[c]));
    }
  }
}

// In 3D the polar balls are drawn at any stage when asked, every k-th pole's, and never the
// balls larger than the samples' box that would wrap the camera.
TEST(Scene, PolarBallsIn3dWithAStride) {
  const auto r = reconstruct(shapes::sphere(800));
  scene::Request request;
  request.stage = scene::Stage::surface;
  EXPECT_EQ(find(scene::build_scene(r, request), "inner-balls"), nullptr);
  request.polar_balls = true;
  request.ball_every = 10;
  const auto scene = scene::build_scene(r, request);
  std::size_t count = 0;
  float diagonal = 0;
  for (int c = 0; c < 3; ++c)
    diagonal += (scene.upper[c] - scene.lower[c]) * (scene.upper[c] - scene.lower[c]);
  for (const char* id : {"polar-balls", "inner-balls", "outer-balls"}) {
    const scene::Layer* balls = find(scene, id);
    ASSERT_NE(balls, nullptr) << id;
    count += balls->radii.size();
    for (float radius : balls->radii) EXPECT_LE(radius, 0.5f * std::sqrt(diagonal));
  }
  EXPECT_GT(count, 0u);
  EXPECT_LE(count, r.poles.poles.size() / 10 + 1);
  // --layers polar-balls names them all.
  request.layers = {"polar-balls"};
  EXPECT_EQ(scene::layer_ids(scene::build_scene(r, request)),
            (std::vector<std::string>{"polar-balls", "inner-balls", "outer-balls"}));
}

TEST(Camera, FitsAndRoundTripsThroughJson) {
  scene::Request request;
  const auto s = scene::build_scene(star(), request);
  const auto camera = render::fit(s);
  EXPECT_EQ(camera.dimension, 2);
  EXPECT_GT(camera.half_height, 0.5f * (s.upper[1] - s.lower[1]));
  const auto back = render::camera_from_json(render::to_json(camera));
  EXPECT_EQ(back.center, camera.center);
  EXPECT_EQ(back.half_height, camera.half_height);
  render::Camera orbit;
  orbit.yaw = 1.25f;
  orbit.target = {1, 2, 3};
  const auto again = render::camera_from_json(render::to_json(orbit));
  EXPECT_EQ(again.yaw, orbit.yaw);
  EXPECT_EQ(again.target, orbit.target);
  EXPECT_THROW(render::camera_from_json(nlohmann::json{{"dimension", 4}}), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
