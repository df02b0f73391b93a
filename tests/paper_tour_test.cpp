// SPDX-License-Identifier: GPL-3.0-or-later
// The paper in the viewer: the tour reaches every panel of every figure (Paper menu, --figure,
// script and keys), each panel's picture is the gallery's (both through the headless renderer,
// within the golden tolerance), and a short tour runs from the keyboard alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "figures/paper_figures.hpp"
#include "render/image.hpp"
#include "viewer/tour.hpp"
#include "viewer_support.hpp"

namespace sculpt {
namespace {

using testing::panel_width;
using testing::run;
using testing::run_viewer_script;

// As the golden images: llvmpipe is deterministic; leave room for Mesa updates.
constexpr int channel_tolerance = 24;
constexpr double allowed_mismatch = 0.005;

std::string panel_id(const figures::Figure& figure, std::size_t panel) {
  return figure.id + figure.images[panel].suffix;
}

// ---------------------------------------------------------------------------------------------
// Navigation

TEST(Tour, NextVisitsEveryPanelOfEveryFigureInOrderAndPreviousComesBack) {
  std::vector<std::string> expected;
  for (const auto& figure : figures::paper_figures()) {
    for (std::size_t i = 0; i < figure.images.size(); ++i) expected.push_back(panel_id(figure, i));
  }
  viewer::Tour tour;
  EXPECT_FALSE(tour.active());
  EXPECT_FALSE(tour.previous()) << "nothing before the tour starts";
  std::vector<std::string> visited;
  while (tour.next()) visited.push_back(tour.panel_id());
  EXPECT_EQ(visited, expected);
  EXPECT_EQ(tour.panel_id(), expected.back()) << "next at the end stays at the end";

  std::vector<std::string> back{tour.panel_id()};
  while (tour.previous()) back.push_back(tour.panel_id());
  std::reverse(back.begin(), back.end());
  EXPECT_EQ(back, expected);
}

TEST(Tour, GoesToAPanelByNumberOrLetterAndRefusesOthers) {
  viewer::Tour tour;
  ASSERT_TRUE(tour.open(*figures::find_figure("fig06")));
  EXPECT_EQ(tour.panel_id(), "fig06a");
  EXPECT_TRUE(tour.go_to("3"));
  EXPECT_EQ(tour.panel_id(), "fig06c");
  EXPECT_TRUE(tour.go_to("e"));
  EXPECT_EQ(tour.panel_name(), "Fig. 6 (e)");
  for (const char* bad : {"0", "6", "z", "", "-1", "99999999999999999999"}) {
    EXPECT_FALSE(tour.go_to(bad)) << bad;
    EXPECT_EQ(tour.panel_id(), "fig06e") << bad;
  }
  EXPECT_TRUE(tour.next_figure());
  EXPECT_EQ(tour.panel_id(), "fig07a");
  EXPECT_TRUE(tour.previous_figure());
  EXPECT_EQ(tour.panel_id(), "fig06a");
  tour.explore();
  EXPECT_TRUE(tour.exploring());
  tour.return_to_panel();
  EXPECT_FALSE(tour.exploring());
}

TEST(Tour, FindsFiguresByTheirNumber) {
  for (const char* id : {"fig06", "fig6", "6", "06"}) {
    ASSERT_NE(figures::find_figure(id), nullptr) << id;
    EXPECT_EQ(figures::find_figure(id)->id, "fig06");
  }
  for (const char* id : {"fig16", "fig00", "fig6x", "x", "", "fig", "fig123"}) {
    EXPECT_EQ(figures::find_figure(id), nullptr) << id;
  }
}

// ---------------------------------------------------------------------------------------------
// In the window

std::size_t drawn_pixels(const render::Image& image, int y0, int y1) {
  std::size_t count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = panel_width + 1; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      count += p[0] < 245 || p[1] < 245 || p[2] < 245;
    }
  }
  return count;
}

// Every panel by "panel next", each on screen as its figure shows it and drawing something;
// each exported through the headless renderer and compared with the gallery's picture.
TEST(PaperTour, ReachesEveryPanelAndEachMatchesTheGallery) {
  const std::string size = "160x160";
  const std::string gallery = std::string(SCULPT_TEST_OUTPUT) + "/tour-gallery";
  const std::string exported = std::string(SCULPT_TEST_OUTPUT) + "/tour-exported";
  std::filesystem::remove_all(gallery);
  std::filesystem::remove_all(exported);
  std::filesystem::create_directories(exported);
  ASSERT_EQ(run(std::string(SCULPT_EXECUTABLE) + " figures --size " + size + " --out " + gallery +
                " > " + gallery + ".log 2>&1"),
            0)
      << testing::read_file(gallery + ".log");

  std::string script = "animation off\n";
  std::vector<std::string> panels;
  for (const auto& figure : figures::paper_figures()) {
    for (std::size_t i = 0; i < figure.images.size(); ++i) {
      const std::string id = panel_id(figure, i);
      script += panels.empty() ? "figure " + figure.id + "\n" : "panel next\n";
      script += "wait\nexpect-panel " + id + "\nframes 1\n";
      script += "screenshot " + exported + "/window-" + id + ".png\n";
      script += "export " + exported + "/" + id + ".png " + size + "\n";
      panels.push_back(id);
    }
  }
  script += "quit\n";
  ASSERT_EQ(run_viewer_script("tour-every-panel", script), 0);

  for (const auto& id : panels) {
    SCOPED_TRACE(id);
    const render::Image window = render::read_png(exported + "/window-" + id + ".png");
    EXPECT_GT(drawn_pixels(window, 30, window.height / 2), 500u) << "the panel draws nothing";
    const render::Image expected = render::read_png(gallery + "/" + id + ".png");
    const render::Image actual = render::read_png(exported + "/" + id + ".png");
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    const render::Comparison comparison = render::compare(expected, actual, channel_tolerance);
    if (comparison.mismatch_ratio > allowed_mismatch) {
      render::write_png(exported + "/" + id + "-diff.png", comparison.difference);
      ADD_FAILURE() << id << ": " << comparison.mismatch_ratio * 100 << "% of pixels differ from "
                    << "the gallery's picture; see " << exported << "/" << id << "-diff.png";
    }
  }
}

// Figs. 2, 4, 5 and 6 from start to end with keys only, the stage and camera moving between
// panels; leaving a panel to explore and coming back; Esc ends the tour.
TEST(PaperTour, AShortTourFromTheKeyboardAlone) {
  const auto step = [](const std::string& key, const std::string& expected) {
    return "key " + key + "\nwait\nexpect-panel " + expected + "\n";
  };
  std::string script = step("pagedown", "fig01a") + step("]", "fig02a") +
                       step("pagedown", "fig02b") + step("pagedown", "fig02c") +
                       step("]", "fig03") + step("]", "fig04a") + step("pagedown", "fig04b") +
                       step("pagedown", "fig05") + step("pagedown", "fig06a") +
                       step("pagedown", "fig06b") + step("pagedown", "fig06c");
  // Exploring from (c): the next stage by hand; T returns to the panel.
  script += "key right\nframes 2\nexpect-panel\n" + step("t", "fig06c");
  script += step("pagedown", "fig06d") + step("pagedown", "fig06e") + step("pageup", "fig06d");
  script += "key escape\nframes 1\nexpect-panel\nquit\n";
  EXPECT_EQ(run_viewer_script("tour-keyboard", script, "--example star"), 0);
}

TEST(PaperTour, OpensAFigureFromTheCommandLine) {
  EXPECT_EQ(run_viewer_script("tour-command-line", "wait\nexpect-panel fig06c\nquit\n",
                              "--figure fig06 --panel c --no-animation"),
            0);
  const std::string log = testing::output_path("tour-no-figure.log");
  EXPECT_EQ(run(std::string(SCULPT_VIEW_EXECUTABLE) + " --figure fig99 >" + log + " 2>&1"), 2);
  EXPECT_NE(testing::read_file(log).find("no figure 'fig99'"), std::string::npos)
      << testing::read_file(log);
}

}  // namespace
}  // namespace sculpt
