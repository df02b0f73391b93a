// SPDX-License-Identifier: GPL-3.0-or-later
// Golden images: every 2D stage of a built-in curve and three 3D stages of a built-in shape,
// rendered headless and compared with tests/golden/*.png within a per-pixel tolerance and a
// mismatch ratio. A failure writes the actual image and a diff next to the build and prints
// their paths. To refresh the goldens on purpose: scripts/update-goldens.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "render/image.hpp"
#include "render_support.hpp"

namespace sculpt {
namespace {

constexpr int image_size = 240;
constexpr int channel_tolerance = 24;  // llvmpipe is deterministic; leave room for Mesa updates
constexpr double allowed_mismatch = 0.005;  // share of pixels beyond the tolerance

struct Golden_case {
  std::string name;
  int dimension;
  scene::Stage stage;
};

std::vector<Golden_case> golden_cases() {
  std::vector<Golden_case> cases;
  for (scene::Stage stage : scene::stages_of(Method::paper, 2)) {
    cases.push_back({std::string("star-") + scene::stage_id(stage), 2, stage});
  }
  for (scene::Stage stage :
       {scene::Stage::outer_concave, scene::Stage::solid, scene::Stage::surface}) {
    cases.push_back({std::string("bumpy-") + scene::stage_id(stage), 3, stage});
  }
  return cases;
}

class Golden_images : public ::testing::TestWithParam<Golden_case> {};

TEST_P(Golden_images, MatchesTheGolden) {
  const Golden_case& c = GetParam();
  scene::Request request;
  request.stage = c.stage;
  request.step = c.stage == scene::Stage::propagation ? 40 : -1;
  const scene::Scene scene = c.dimension == 2
                                 ? scene::build_scene(testing::star_reconstruction(), request)
                                 : scene::build_scene(testing::bumpy_reconstruction(), request);
  const render::Image actual = testing::render_scene(scene, image_size, /*legend=*/true);

  const std::string golden = std::string(SCULPT_GOLDEN_DIR) + "/" + c.name + ".png";
  if (std::getenv("SCULPT_UPDATE_GOLDEN")) {
    render::write_png(golden, actual);
    std::cout << "updated " << golden << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden))
      << golden << " is missing: run scripts/update-goldens to create it";
  const render::Image expected = render::read_png(golden);
  const render::Comparison comparison = render::compare(expected, actual, channel_tolerance);
  if (comparison.mismatch_ratio > allowed_mismatch) {
    const std::string stem = std::string(SCULPT_TEST_OUTPUT) + "/golden-failures/" + c.name;
    std::filesystem::create_directories(std::string(SCULPT_TEST_OUTPUT) + "/golden-failures");
    render::write_png(stem + ".actual.png", actual);
    if (!comparison.difference.rgba.empty())
      render::write_png(stem + ".diff.png", comparison.difference);
    ADD_FAILURE() << c.name << ": " << comparison.mismatch_ratio * 100
                  << "% of pixels differ by more than " << channel_tolerance
                  << " (largest difference " << comparison.largest_difference << ")\n"
                  << "  expected: " << golden << "\n  actual:   " << stem << ".actual.png\n"
                  << "  diff:     " << stem << ".diff.png";
  }
}

INSTANTIATE_TEST_SUITE_P(Stages, Golden_images, ::testing::ValuesIn(golden_cases()),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

TEST(Golden_comparison, DetectsAChangedPicture) {
  // The comparison itself must be able to fail: a moved camera is a different picture.
  scene::Request request;
  request.stage = scene::Stage::surface;
  const auto scene = scene::build_scene(testing::star_reconstruction(), request);
  const auto a = testing::render_scene(scene, 120);
  auto camera = render::fit(scene);
  camera.center.x += 0.2f;
  render::Draw_options plain;
  plain.legend = plain.title = false;
  const auto b = testing::headless().render(scene, camera, 120, 120, plain);
  EXPECT_GT(render::compare(a, b, channel_tolerance).mismatch_ratio, allowed_mismatch);
  EXPECT_EQ(render::compare(a, a, 0).mismatch_ratio, 0.0);
}

}  // namespace
}  // namespace sculpt
