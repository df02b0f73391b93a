// SPDX-License-Identifier: GPL-3.0-or-later
// A layer that silently disappears must fail a test, not only drift pixels: every layer of
// every stage puts something on screen, removing it changes the picture, and the paper's
// colours are where they belong.
#include <gtest/gtest.h>

#include <algorithm>

#include "frontend/shots.hpp"
#include "render/image.hpp"
#include "render/legend_layout.hpp"
#include "render_support.hpp"
#include "scene/palette.hpp"

namespace sculpt {
namespace {

// The scene's bounds widened to everything it draws: convex poles lie near the box, far
// outside the samples' frame (as in the paper's Fig. 6c).
scene::Scene framing_everything(scene::Scene scene) {
  for (const auto& layer : scene.layers) {
    for (std::size_t i = 0; i < layer.positions.size(); ++i) {
      const float radius = layer.radii.empty() ? 0.0f : layer.radii[i];
      for (int k = 0; k < 3; ++k) {
        scene.lower[k] = std::min(scene.lower[k], layer.positions[i][k] - radius);
        scene.upper[k] = std::max(scene.upper[k], layer.positions[i][k] + radius);
      }
    }
  }
  return scene;
}

template <int D>
void expect_every_layer_visible(const Reconstruction<D>& reconstruction) {
  for (scene::Stage stage :
       scene::stages_of(reconstruction.options.method, reconstruction.dimension)) {
    scene::Request request;
    request.stage = stage;
    const scene::Scene framed = scene::build_scene(reconstruction, request);
    const scene::Scene full = framing_everything(framed);
    ASSERT_FALSE(full.layers.empty()) << scene::stage_id(stage);
    const render::Image all = testing::render_scene(framed, 160);
    for (std::size_t i = 0; i < full.layers.size(); ++i) {
      const auto& layer = full.layers[i];
      SCOPED_TRACE(std::string(scene::stage_id(stage)) + " / " + layer.id);
      // Once the propagation is over, no pole may be left unlabelled (the stage's data says so).
      if (layer.id == "unlabelled-poles" && reconstruction.propagation.unlabelled == 0) {
        EXPECT_TRUE(layer.positions.empty());
        continue;
      }
      EXPECT_FALSE(layer.positions.empty());
      scene::Scene alone = full, without = framed;
      alone.layers = {layer};
      without.layers.erase(without.layers.begin() + static_cast<long>(i));
      EXPECT_GT(testing::non_background_pixels(testing::render_scene(alone, 160)), 0u);
      // In the usual frame, each layer that reaches into it leaves a mark on the picture. Not
      // in 3D, where a layer may be hidden behind another (inner poles in the sample cloud).
      const bool in_frame =
          std::any_of(layer.positions.begin(), layer.positions.end(), [&](const scene::Vec3& p) {
            return p[0] >= framed.lower[0] && p[0] <= framed.upper[0] && p[1] >= framed.lower[1] &&
                   p[1] <= framed.upper[1];
          });
      if (D == 2 && in_frame) {
        EXPECT_GT(render::compare(all, testing::render_scene(without, 160), 0).mismatch_ratio, 0.0)
            << "removing the layer changes nothing";
      }
    }
  }
}

TEST(Render_layers, EveryLayerOfEveryStageShows2d) {
  expect_every_layer_visible(testing::star_reconstruction());
}

TEST(Render_layers, EveryLayerOfEveryStageShows3d) {
  expect_every_layer_visible(testing::bumpy_reconstruction());
}

std::size_t pixels_of(const render::Image& image, scene::Color c) {
  return render::count_pixels_near(image, c.r, c.g, c.b, 12);
}

TEST(Render_layers, PaperColoursAppear) {
  scene::Request request;
  request.stage = scene::Stage::outer_concave;
  const auto poles_2d =
      testing::render_scene(scene::build_scene(testing::star_reconstruction(), request), 240);
  EXPECT_GT(pixels_of(poles_2d, scene::palette::sample), 100u) << "green samples";
  EXPECT_GT(pixels_of(poles_2d, scene::palette::inner_pole), 100u) << "red inner poles";
  EXPECT_GT(pixels_of(poles_2d, scene::palette::outer_pole_2d), 50u) << "blue outer concave poles";

  const auto poles_3d =
      testing::render_scene(scene::build_scene(testing::bumpy_reconstruction(), request), 240);
  EXPECT_GT(pixels_of(poles_3d, scene::palette::outer_pole_3d), 50u)
      << "orange outer concave poles";

  request.stage = scene::Stage::delaunay;
  const auto delaunay =
      testing::render_scene(scene::build_scene(testing::star_reconstruction(), request), 240);
  EXPECT_GT(pixels_of(delaunay, scene::palette::delaunay_edge), 500u) << "blue Delaunay edges";

  request.stage = scene::Stage::surface;
  const auto curve =
      testing::render_scene(scene::build_scene(testing::star_reconstruction(), request), 240);
  EXPECT_GT(pixels_of(curve, scene::palette::curve), 100u) << "the black curve";
  const auto surface =
      testing::render_scene(scene::build_scene(testing::bumpy_reconstruction(), request), 240);
  EXPECT_GT(testing::non_background_pixels(surface), 240u * 240u / 10) << "a shaded surface";
}

TEST(Render_layers, RenderingIsDeterministic) {
  scene::Request request;
  request.stage = scene::Stage::solid;
  const auto scene = scene::build_scene(testing::bumpy_reconstruction(), request);
  const auto a = testing::render_scene(scene, 128), b = testing::render_scene(scene, 128);
  EXPECT_EQ(a.rgba, b.rgba);
}

TEST(Render_layers, ReportsLlvmpipe) {
  EXPECT_NE(std::string(testing::headless().gl_renderer()).find("llvmpipe"), std::string::npos);
}

// A 2D scene framed on the square [-1, 1]^2 with one layer of points, none yet.
scene::Scene points_in_square(const char* label) {
  scene::Scene scene;
  scene.dimension = 2;
  scene.lower = {-1, -1, 0};
  scene.upper = {1, 1, 0};
  scene::Layer points;
  points.id = "points";
  points.label = label;
  points.color = {0.1f, 0.3f, 0.8f};
  scene.layers = {points};
  return scene;
}

// The legend takes the corner clearest of the data: off a shape that fills the top left, into
// the empty top right; and stays top left when that is clear.
TEST(Render_layers, TheLegendMovesOffTheData) {
  const auto legend_pixels = [](const render::Image& image, int x0, int y0, int x1, int y1) {
    std::size_t count = 0;  // the legend's box is 0.98 grey, which nothing else is
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const auto* p = image.pixel(x, y);
        count += p[0] == 250 && p[1] == 250 && p[2] == 250;
      }
    }
    return count;
  };
  scene::Scene scene = points_in_square("shape");
  scene.layers[0].size = 6;
  // Past the bounds the camera frames, so that the shape reaches the picture's corner.
  auto& positions = scene.layers[0].positions;
  for (float x = -1.5f; x <= 0; x += 0.02f) {
    for (float y = 0; y <= 1.5f; y += 0.02f) positions.push_back({x, y, 0});
  }
  positions.push_back({1, -1, 0});  // the bottom right corner of the bounds
  const render::Image moved = testing::render_scene(scene, 300, /*legend=*/true);
  EXPECT_EQ(legend_pixels(moved, 0, 0, 60, 40), 0u);
  EXPECT_GT(legend_pixels(moved, 150, 0, 300, 40), 200u);
  // Mirrored to the bottom right: the top left is clear, and the legend stays there.
  for (auto& p : scene.layers[0].positions) p = {-p[0], -p[1], 0};
  scene.layers[0].positions.back() = {1, -1, 0};  // no point left in the top left
  const render::Image kept = testing::render_scene(scene, 300, /*legend=*/true);
  EXPECT_GT(legend_pixels(kept, 0, 0, 150, 40), 200u);
  EXPECT_EQ(legend_pixels(kept, 150, 0, 300, 40), 0u);
}

// A square filled with points: the fit puts data in every corner of the picture.
scene::Scene filled_square(float far_out = 0) {
  scene::Scene scene = points_in_square("a square of points");
  auto& positions = scene.layers[0].positions;
  for (float x = -1; x <= 1; x += 0.05f) {
    for (float y = -1; y <= 1; y += 0.05f) positions.push_back({x, y, 0});
  }
  // Points strewn far beyond the bounds, as convex poles are: in every corner at any zoom.
  if (far_out > 0) {
    for (float x = -far_out; x <= far_out; x += 0.1f) {
      for (float y = -far_out; y <= far_out; y += 0.1f) positions.push_back({x, y, 0});
    }
  }
  return scene;
}

// Exports do as the viewer does: a fitted camera steps back until the legend has a corner clear
// of data; a camera given, or a zoom on a detail, stays; and where no step back would clear a
// corner (data strewn to every corner), the fit stays and the shape keeps its size.
TEST(Render_layers, AFittedExportStepsBackForItsLegend) {
  render::Draw_options options;
  const scene::Scene square = filled_square();
  const render::Legend_layout layout(square);
  const render::Camera fitted = render::fit(square, 1.0f);
  ASSERT_TRUE(layout.over_data(fitted, 300, 300, options));
  int steps = 0;
  const render::Camera stepped =
      render::with_room_for_legend(layout, fitted, 300, 300, options, &steps);
  EXPECT_GE(steps, 1);
  EXPECT_LE(steps, 3);
  EXPECT_FALSE(layout.over_data(stepped, 300, 300, options));

  // Strewn to every corner however far back: the fit stays, the legend where least is.
  const scene::Scene strewn = filled_square(5);
  const render::Legend_layout strewn_layout(strewn);
  const render::Camera strewn_fit = render::fit(strewn, 1.0f);
  ASSERT_TRUE(strewn_layout.over_data(strewn_fit, 300, 300, options));
  const render::Camera kept_fit =
      render::with_room_for_legend(strewn_layout, strewn_fit, 300, 300, options, &steps);
  EXPECT_EQ(steps, 0);
  EXPECT_EQ(render::to_json(kept_fit), render::to_json(strewn_fit));

  // Through the shots, as `sculpt render` and the gallery draw.
  frontend::Shot shot;
  shot.size = "300x300";
  EXPECT_GT(frontend::draw_scene(testing::headless(), shot, square).legend_steps, 0);
  // A zoom on a detail stays, though stepping back would clear a corner.
  frontend::Shot detail = shot;
  detail.zoom = 0.95;
  render::with_room_for_legend(layout,
                               render::fit(square, 1.0f, 0.95f, float(shot.yaw), float(shot.pitch)),
                               300, 300, options, &steps);
  ASSERT_GE(steps, 1);
  EXPECT_EQ(frontend::draw_scene(testing::headless(), detail, square).legend_steps, 0);
  // An animation's frames step back three times at most in all.
  EXPECT_EQ(frontend::draw_scene(testing::headless(), shot, square, nullptr, 3).legend_steps, 3);
  const nlohmann::json given = render::to_json(fitted);
  const frontend::Picture kept = frontend::draw_scene(testing::headless(), shot, square, &given);
  EXPECT_EQ(kept.legend_steps, 0);
  EXPECT_EQ(render::to_json(kept.camera), given);
}

}  // namespace
}  // namespace sculpt
