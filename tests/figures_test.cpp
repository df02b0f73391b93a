// SPDX-License-Identifier: GPL-3.0-or-later
// `sculpt figures`: the list covers every figure of the paper, each image is written, shows
// something, and every layer it was drawn with has content; the tables and gallery are there.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "figures/cgal_meshes.hpp"
#include "figures/gallery.hpp"
#include "file_support.hpp"
#include "frontend/shot_renderer.hpp"
#include "render/image.hpp"

namespace sculpt {
namespace {

TEST(Figures, TheListCoversEveryFigureOfThePaper) {
  std::set<std::string> ids;
  for (const auto& figure : figures::paper_figures()) {
    ids.insert(figure.id);
    EXPECT_FALSE(figure.images.empty()) << figure.id;
    EXPECT_EQ(figure.caption.rfind("Fig. ", 0), 0u) << figure.id;
    EXPECT_FALSE(figure.data.empty()) << figure.id;
    EXPECT_NE(figure.sentence.find("Fig"), std::string::npos)
        << figure.id << ": the paper's sentence names the figure";
    for (const auto& image : figure.images) {
      EXPECT_FALSE(image.what.empty()) << figure.id << image.suffix;
      EXPECT_GT(image.why.size(), 20u) << figure.id << image.suffix << ": say what changed";
    }
  }
  for (int n = 1; n <= 15; ++n) {
    const std::string id = (n < 10 ? "fig0" : "fig") + std::to_string(n);
    EXPECT_TRUE(ids.count(id)) << id << " is missing";
  }
}

// What each panel's text claims of its result holds on the panel's own input: the figures that
// contradict the paper say so in numbers we can check (paper_figures.hpp, Claim).
TEST(Figures, EveryPanelsClaimHoldsOnItsInput) {
  figures::Cgal_meshes cgal;
  frontend::Shot_renderer renderer;
  int claims = 0;
  for (const auto& figure : figures::paper_figures()) {
    for (const auto& image : figure.images) {
      if (!image.claim.asserted) continue;
      ++claims;
      const std::string panel = figure.id + image.suffix;
      const Statistics stats = std::visit([](const auto& r) { return r.stats; },
                                          renderer.reconstruction(cgal.resolve(image.shot)));
      const figures::Claim& claim = image.claim;
      const bool closed_manifold = stats.boundary_ridges == 0 && stats.non_manifold_ridges == 0 &&
                                   stats.non_manifold_vertices == 0;
      if (claim.closed_manifold) {
        EXPECT_TRUE(closed_manifold) << panel;
      }
      const auto within = [&](std::size_t count, figures::Count_range range, const char* what) {
        EXPECT_GE(long(count), range.at_least) << panel << ": " << what;
        if (range.at_most >= 0) {
          EXPECT_LE(long(count), range.at_most) << panel << ": " << what;
        }
      };
      within(stats.non_manifold_ridges, claim.non_manifold_edges, "non-manifold edges");
      within(stats.unused_samples, claim.samples_left_off, "samples left off");
      within(stats.boundary_ridges, claim.border_edges, "border edges");
      if (claim.components > 0) {
        EXPECT_EQ(long(stats.components), claim.components) << panel;
      }
      if (claim.border_loops >= 0) {
        EXPECT_EQ(long(stats.boundary_loops), claim.border_loops) << panel;
      }
    }
    // A figure that contradicts the paper says so on screen, and shows a result beside it.
    if (!figure.contradiction.empty()) {
      EXPECT_TRUE(std::any_of(figure.images.begin(), figure.images.end(),
                              [](const auto& image) { return image.claim.asserted; }))
          << figure.id << ": its contradiction is checked";
    }
  }
  EXPECT_GE(claims, 6);
}

TEST(Figures, GeneratesEveryImageWithItsLayers) {
  const std::string out = std::string(SCULPT_TEST_OUTPUT) + "/figures";
  std::filesystem::remove_all(out);
  const std::string command = std::string(SCULPT_EXECUTABLE) + " figures --size 240x240 --out " +
                              out + " > " + out + ".log 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << testing::read_file(out + ".log");

  const auto manifest = nlohmann::json::parse(testing::read_file(out + "/figures.json"));
  std::size_t images = 0;
  for (const auto& figure : manifest) {
    for (const auto& image : figure["images"]) {
      const std::string file = out + "/" + image["file"].get<std::string>();
      SCOPED_TRACE(file);
      ASSERT_TRUE(std::filesystem::exists(file));
      const render::Image picture = render::read_png(file);
      std::size_t drawn = 0;
      for (std::size_t i = 0; i < picture.rgba.size(); i += 4) {
        drawn += picture.rgba[i] < 240 || picture.rgba[i + 1] < 240 || picture.rgba[i + 2] < 240;
      }
      EXPECT_GT(drawn, picture.rgba.size() / 4 / 50) << "the image is (nearly) empty";
      ASSERT_FALSE(image["layers"].empty());
      for (const auto& [layer, count] : image["layers"].items()) {
        if (layer == "unlabelled-poles") continue;  // empty once every pole has a label
        EXPECT_GT(count.get<std::size_t>(), 0u) << "layer " << layer << " is empty";
      }
      ++images;
    }
  }
  std::size_t listed = 0;
  for (const auto& figure : figures::paper_figures()) listed += figure.images.size();
  EXPECT_EQ(images, listed);
  for (const char* name : {"README.md", "table1.md", "table2.md"}) {
    EXPECT_GT(std::filesystem::file_size(out + "/" + name), 200u) << name;
  }
  const std::string gallery = testing::read_file(out + "/README.md");
  // Every column of the paper's comparisons: the power crust, both co-cones, Table 2's.
  for (const char* file :
       {"fig15a-femur.png", "fig14b.png", "fig15b-femur.png", "fig15c-knot.png"}) {
    EXPECT_NE(gallery.find(file), std::string::npos) << file;
  }
  EXPECT_NE(testing::read_file(out + "/table2.md").find("verdict of the tight co-cone"),
            std::string::npos);
  EXPECT_NE(gallery.find("label q like p"), std::string::npos) << "Fig. 5's pseudo-code";
}

}  // namespace
}  // namespace sculpt
