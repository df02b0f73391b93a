// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer in a real window under Xvfb, driven by scripts: it steps through every stage of a
// 2D and a 3D example, its pictures change from stage to stage with the panel present, it keeps
// drawing while a 100k-point reconstruction runs, it saves pictures through the headless
// renderer, and without a display it says how to render headless.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>
#include <vector>

#include "file_support.hpp"
#include "frontend/explanations.hpp"
#include "frontend/input.hpp"
#include "render/image.hpp"
#include "scene/palette.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"
#include "viewer/panel_colours.hpp"
#include "viewer_support.hpp"

namespace sculpt {
namespace {

using testing::panel_width;
using testing::run;
using testing::run_viewer_script;

std::string fmt_point(const Point<3>& p) {
  return std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
}

std::size_t dark_pixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  std::size_t count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto* p = image.pixel(x, y);
      count += p[0] < 70 && p[1] < 70 && p[2] < 70;
    }
  }
  return count;
}

std::size_t drawn_pixels(const render::Image& image) {
  std::size_t count = 0;
  for (int y = 30; y < image.height; ++y) {
    for (int x = panel_width + 1; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      count += p[0] < 245 || p[1] < 245 || p[2] < 245;
    }
  }
  return count;
}

TEST(Viewer, StepsThroughEveryStageIn2dAnd3d) {
  std::string script;
  std::vector<std::string> shots;
  for (const std::string example : {"star", "bumpy"}) {
    script += "example " + example + "\nwait\n";
    for (scene::Stage stage : scene::stages_of(Method::robust, 3)) {
      const std::string shot =
          testing::output_path("viewer-" + example + "-" + scene::stage_id(stage) + ".png");
      script +=
          std::string("stage ") + scene::stage_id(stage) + "\nframes 2\nscreenshot " + shot + "\n";
      shots.push_back(shot);
    }
  }
  script += "quit\n";
  ASSERT_EQ(run_viewer_script("tour", script), 0);

  std::optional<render::Image> previous;
  for (const auto& shot : shots) {
    SCOPED_TRACE(shot);
    ASSERT_TRUE(std::filesystem::exists(shot));
    const render::Image image = render::read_png(shot);
    ASSERT_GT(image.width, panel_width + 100);
    EXPECT_GT(drawn_pixels(image), 500u) << "the stage draws nothing";
    // The panel: ImGui's dark window fills the left strip below the menu bar (a third at
    // least: its headers are lighter bars).
    const std::size_t panel = std::size_t(panel_width - 20) * 200;
    EXPECT_GT(dark_pixels(image, 10, 40, panel_width - 10, 240), panel / 3) << "no UI panel";
    if (previous) {
      EXPECT_GT(render::compare(*previous, image, 8).mismatch_ratio, 0.001)
          << "same picture as the stage before";
    }
    previous = image;
  }
}

TEST(Viewer, StaysResponsiveWhileAHundredThousandPointsReconstruct) {
  std::string points;
  for (const auto& p : shapes::torus(100000)) {
    points += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  }
  const std::string input = testing::write_file("torus-100k.xyz", points);
  // Frames keep coming while the job runs; cancelling returns to an idle window.
  EXPECT_EQ(run_viewer_script("responsive", "open " + input +
                                                "\nframes 5\nexpect-busy\nframes 5\nexpect-busy\n"
                                                "cancel\nwait-idle\nframes 2\nquit\n"),
            0);
}

TEST(Viewer, SavesPicturesThroughTheHeadlessRenderer) {
  const std::string picture = testing::output_path("viewer-export.png");
  ASSERT_EQ(run_viewer_script("export",
                              "example star\nwait\nstage poles\npick-sample 3\nframes 1\nexport " +
                                  picture + " 400x300\nquit\n"),
            0);
  const render::Image image = render::read_png(picture);
  EXPECT_EQ(image.width, 400);
  EXPECT_EQ(image.height, 300);
}

// A script is input too: each malformed command gets its own line and the run fails, without
// a crash, and the viewer goes on to the next command (the last one still takes effect).
TEST(Viewer, AMalformedScriptCommandIsOneLineAndAFailureNotACrash) {
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"pick-sample 99999", "no sample 99999"},
      {"pick-pole 5000000", "no pole 5000000"},
      {"step abc", "'step abc'"},
      {"step 99999999999999999999999", "expected a number"},
      {"frames x", "'frames x'"},
      {"export", "needs a PNG path"},
      {"export e.png 12xy", "WIDTHxHEIGHT"},
      {"screenshot", "needs a PNG path"},
      {"screenshot shot.bmp", "must end in .png"},
      {"save-points star.png", "saved as .xy text"},
      {"animation maybe", "on or off"},
      {"figure fig99", "no figure 'fig99'"},
      {"stage nowhere", "no stage 'nowhere'"},
      {"stage crust-delaunay", "no stage 'crust-delaunay'"},
      {"method nowhere", "no method 'nowhere'"},
      {"camera spin", "expected camera fit"},
      {"camera zoom -2", "expected camera fit"},
      {"follow sometimes", "follow on or off"},
      {"export-animation a.webp 10", "WIDTHxHEIGHT"}};
  // The camera commands that are right move the camera and fail nothing.
  std::string script =
      "example star\nwait\ncamera zoom 0.5\ncamera pan 0.1 0\ncamera orbit 30 "
      "10\ncamera fit\n";
  for (const auto& [command, _] : commands) script += command + "\n";
  const std::string picture = testing::output_path("after-bad-commands.png");
  script += "pick-sample 3\nframes 1\nexport " + picture + " 64x48\nquit\n";
  EXPECT_EQ(run_viewer_script("malformed", script), 1);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/malformed.log");
  for (const auto& [command, says] : commands) {
    EXPECT_NE(log.find(says), std::string::npos) << command << " should say " << says << ":\n"
                                                 << log;
  }
  std::size_t complaints = 0;
  for (std::size_t at = log.find("script:"); at != std::string::npos;
       at = log.find("script:", at + 1)) {
    ++complaints;
  }
  EXPECT_EQ(complaints, commands.size()) << log;
  EXPECT_EQ(render::read_png(picture).width, 64);
}

// What did not happen is a failure: a file that could not be opened behind an older result, a
// script that is a folder or binary, a save over the file the viewer opened.
TEST(Viewer, FailuresAreFailures) {
  EXPECT_EQ(
      run_viewer_script("open-bad", "example star\nwait\nopen /nonexistent/p.xy\nwait\nquit\n"), 1);
  EXPECT_NE(testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/open-bad.log")
                .find("no reconstruction"),
            std::string::npos);

  const std::string input = testing::write_file("viewer-input.xy", [] {
    std::string text;
    for (int i = 0; i < 40; ++i)
      text +=
          std::to_string(std::cos(0.157 * i)) + " " + std::to_string(std::sin(0.157 * i)) + "\n";
    return text;
  }());
  const std::string before = testing::read_file(input);
  EXPECT_EQ(run_viewer_script("save-over-input", "open " + input + "\nwait\nsave-points " + input +
                                                     "\nsave-result " + input + "\nquit\n"),
            1);
  EXPECT_EQ(testing::read_file(input), before) << "the input is intact";
  EXPECT_NE(testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/save-over-input.log")
                .find("never replaces an input"),
            std::string::npos);

  const std::string folder = std::string(SCULPT_TEST_OUTPUT) + "/a-script-folder";
  std::filesystem::create_directories(folder);
  const std::string binary = testing::write_file("binary.script", std::string("wait\0\x01\x02", 7));
  for (const std::string& script : {folder, binary}) {
    const std::string log = testing::output_path("bad-script.log");
    EXPECT_NE(run("xvfb-run -a " + std::string(SCULPT_VIEW_EXECUTABLE) + " --script " + script +
                  " >" + log + " 2>&1"),
              0)
        << script;
    EXPECT_NE(testing::read_file(log).find("script"), std::string::npos) << testing::read_file(log);
  }
}

// A class flips between methods on the same points; each method's own stages can be shown.
TEST(Viewer, SwitchesMethodOnTheSamePoints) {
  const std::string crust = testing::output_path("viewer-crust.png");
  EXPECT_EQ(run_viewer_script("methods",
                              "example blob\nwait\nmethod crust\nwait\nstage crust-delaunay\n"
                              "frames 2\nscreenshot " +
                                  crust +
                                  "\nmethod nn-crust\nwait\nstage surface\nframes 1\n"
                                  "method paper\nwait\nstage propagation\nframes 1\nquit\n"),
            0);
  EXPECT_GT(render::read_png(crust).width, 0);
}

// The Explanation panel follows the method and the stage; `explain` prints it.
TEST(Viewer, ExplainsTheStageOnScreenForTheMethodThatRan) {
  ASSERT_EQ(run_viewer_script("explain",
                              "example bumpy\nwait\nstage poles\nexplain\nmethod tight-cocone\n"
                              "wait\nstage solid\nexplain\nmethod power-crust\nwait\n"
                              "stage surface\nexplain\nquit\n"),
            0);
  // (output_path would remove the log: it makes a fresh path.)
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/explain.log");
  EXPECT_NE(log.find("explain poles: " + frontend::explanation(Method::robust, Surface_kind::closed,
                                                               3, scene::Stage::poles)),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("explain solid: The cells the peeling did not reach"), std::string::npos)
      << log;
  EXPECT_NE(log.find("explain surface: The reconstruction: triangles near the samples"),
            std::string::npos)
      << log;
  // Before any reconstruction there is nothing to explain: one line, a failed run.
  EXPECT_EQ(run_viewer_script("explain-nothing", "explain\nquit\n", "--example nonexistent"), 1);
}

TEST(Viewer, OpensAScanWithRepeatedPointsWhenToldToMergeThem) {
  std::string text;
  for (const auto& p : shapes::sphere(500)) text += fmt_point(p);
  text += fmt_point(shapes::sphere(500)[7]);  // a scan's repeated point
  const std::string scan = testing::write_file("repeated.xyz", text);
  EXPECT_NE(run_viewer_script("repeated-refused", "wait\nquit\n", scan), 0);
  EXPECT_EQ(run_viewer_script("repeated-merged", "wait\nquit\n", "--merge-duplicates " + scan), 0);
}

TEST(Viewer, TakesItsWindowSizeAsWidthByHeight) {
  const std::string shot = testing::output_path("viewer-size.png");
  EXPECT_EQ(run_viewer_script("size", "wait\nscreenshot " + shot + "\nquit\n", "--size 1024x600"),
            0);
  const auto image = render::read_png(shot);
  EXPECT_EQ(image.width, 1024);
  EXPECT_EQ(image.height, 600);
  const int code = run(std::string(SCULPT_VIEW_EXECUTABLE) + " --size 1024 >/dev/null 2>&1");
  EXPECT_EQ(code, 2);  // a width alone is a usage error, in one line
}

// The share of the drawing area (right of the panel) covered by its most common colour other
// than the white background: near 1 for a wall of one colour.
double most_common_colour_share(const render::Image& image, int left = panel_width + 1,
                                int top = 30) {
  std::map<std::uint32_t, std::size_t> counts;
  std::size_t total = 0;
  for (int y = top; y < image.height; ++y) {
    for (int x = left; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      const std::uint32_t colour = (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
      ++total;
      if (colour != 0xffffff) ++counts[colour];
    }
  }
  std::size_t most = 0;
  for (const auto& [colour, count] : counts) most = std::max(most, count);
  return double(most) / double(total);
}

TEST(Viewer, ACutAwayShowsInsideTheDelaunayTriangulation) {
  const std::string whole = testing::output_path("viewer-delaunay-whole.png"),
                    cut = testing::output_path("viewer-delaunay-cut.png");
  ASSERT_EQ(
      run_viewer_script("cut-away", "example bumpy\nwait\nstage delaunay\nframes 2\nscreenshot " +
                                        whole + "\nclip 0.5 30 60 0.06\nframes 2\nscreenshot " +
                                        cut + "\nclip off\nclip 2 0 0\nquit\n"),
      1);  // the last command is refused: a position beyond 1
  const double whole_share = most_common_colour_share(render::read_png(whole));
  const double cut_share = most_common_colour_share(render::read_png(cut));
  // Whole, the edges are a wall of one colour; cut, the cells behind the plane are seen apart,
  // their edges with space between them.
  EXPECT_LT(cut_share, 0.5) << "whole: " << whole_share;
  EXPECT_LT(cut_share, whole_share / 2) << "whole: " << whole_share;
  std::cout << "cut-away: " << cut_share << " of the drawing area one colour, whole " << whole_share
            << "\n";
}

// Share of the window right of the panel that is exactly this colour (an unlit fill).
double share_of_colour(const render::Image& image, const scene::Color& colour) {
  const auto level = [](float c) { return int(std::lround(255 * c)); };
  std::size_t total = 0, matching = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = panel_width + 1; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      ++total;
      matching += std::abs(p[0] - level(colour.r)) <= 2 && std::abs(p[1] - level(colour.g)) <= 2 &&
                  std::abs(p[2] - level(colour.b)) <= 2;
    }
  }
  return double(matching) / double(total);
}

// Share of the window right of the panel in this colour lit at any strength: the pixel's
// chromaticity (its channels over their sum) within 0.015 of the colour's, white and black apart.
double share_of_shade(const render::Image& image, const scene::Color& colour) {
  const float sum = colour.r + colour.g + colour.b;
  const float r = colour.r / sum, g = colour.g / sum;
  std::size_t total = 0, matching = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = panel_width + 1; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      ++total;
      const int level = p[0] + p[1] + p[2];
      if (level < 90 || level > 735) continue;
      matching += std::abs(float(p[0]) / float(level) - r) <= 0.015f &&
                  std::abs(float(p[1]) / float(level) - g) <= 0.015f;
    }
  }
  return double(matching) / double(total);
}

// In section, the paper method's DT(S + OUP) of a torus reads as its Fig. 1: the tube's two
// discs kept, the cells with an inserted pole sculpted away around them, seen along the plane.
TEST(Viewer, ASectionShowsTheCellsKeptAndSculptedAway) {
  const std::string picture = testing::output_path("viewer-section.png");
  ASSERT_EQ(run_viewer_script("section",
                              "example torus\nmethod paper\nwait\nstage sculpted-delaunay\n"
                              "section 0.5 0 0\nframes 2\nscreenshot " +
                                  picture + "\nsection 0.5 0 0 7\nquit\n"),
            1);  // the last command is refused: a fourth number
  const render::Image image = render::read_png(picture);
  const double kept = share_of_colour(image, scene::palette::solid);
  const double away = share_of_colour(image, scene::palette::sculpted_away);
  EXPECT_GT(kept, 0.01) << "away " << away;
  EXPECT_GT(away, 0.05) << "kept " << kept;
  std::cout << "section: " << kept << " of the view kept cells, " << away << " sculpted away\n";
}

// The carving replayed in the window: `replay carving` shows the hull whole and plays it, the
// step's cells lit, to the solid; a stage that does not replay is refused.
TEST(Viewer, TheCarvingReplaysFromTheHullToTheSolid) {
  const std::string start = testing::output_path("viewer-carving-start.png"),
                    middle = testing::output_path("viewer-carving-middle.png"),
                    end = testing::output_path("viewer-carving-end.png");
  ASSERT_EQ(run_viewer_script("carving",
                              "example star\nmethod paper\nwait\nreplay carving\nstep 0\n"
                              "frames 2\nscreenshot " +
                                  start + "\nstep 12\nframes 2\nscreenshot " + middle +
                                  "\nreplay carving 100\nwait-replay\nframes 2\nscreenshot " + end +
                                  "\nlink\nreplay solid\nquit\n"),
            1);  // the last command is refused: the solid does not replay
  const auto share = [](const std::string& path, scene::Color colour) {
    return share_of_colour(render::read_png(path), colour);
  };
  EXPECT_EQ(share(start, scene::palette::sculpted_away), 0.0);
  EXPECT_GT(share(middle, scene::palette::sculpted_away), 0.002);
  EXPECT_GT(share(middle, scene::palette::just_removed), 0.0);
  // Played to its end: the last step's cells are lit, and the rest sculpted away.
  EXPECT_GT(share(end, scene::palette::sculpted_away),
            share(middle, scene::palette::sculpted_away));
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/carving.log");
  EXPECT_NE(log.find("--stage carving"), std::string::npos) << log;
  EXPECT_NE(
      log.find("replay propagation (the labelling), carving, candidates (the pruning), front"),
      std::string::npos)
      << log;
}

// The peers that grow replay too: the Advancing Front's surface spreads over the torus triangle
// by triangle, and the alpha shape's solid grows from the samples alone, through the method's
// own alpha (where the stage opens), to the hull.
TEST(Viewer, ThePeersGrowStepByStep) {
  std::map<std::string, std::string> paths;  // output_path clears the file: called once a name
  const auto shot = [&](const std::string& name) -> const std::string& {
    auto found = paths.find(name);
    if (found == paths.end())
      found = paths.emplace(name, testing::output_path(name + ".png")).first;
    return found->second;
  };
  ASSERT_EQ(
      run_viewer_script(
          "growth",
          "example torus\nmethod advancing-front\nwait\nreplay front\nstep 0\nframes 2\n"
          "screenshot " +
              shot("front-start") + "\nstep 3000\nframes 2\nscreenshot " + shot("front-middle") +
              "\nreplay front 2000\nwait-replay\nframes 2\n"
              "screenshot " +
              shot("front-end") +
              "\nmethod alpha-shape\nwait\n"
              "stage alpha\nframes 2\nscreenshot " +
              shot("alpha-own") + "\nstep 0\nframes 2\nscreenshot " + shot("alpha-start") +
              "\nlink\nquit\n"),
      0);
  const auto share = [&](const std::string& name, scene::Color colour) {
    return share_of_colour(render::read_png(shot(name)), colour);
  };
  const auto grown = [&](const std::string& name) {
    return share_of_shade(render::read_png(shot(name)), scene::palette::surface);
  };
  // Differences between frames: the panel's greys are the same in each.
  EXPECT_GT(grown("front-middle"), grown("front-start") + 0.01);
  EXPECT_GT(grown("front-end"), grown("front-middle"));
  EXPECT_GT(share("front-middle", scene::palette::border), 0.0005);  // the front's edges
  EXPECT_EQ(share("front-end", scene::palette::border), 0.0);        // closed: no front left
  const auto solid = [&](const std::string& name) {
    return share_of_shade(render::read_png(shot(name)), scene::palette::solid);
  };
  EXPECT_GT(solid("alpha-own"), solid("alpha-start") + 0.05);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/growth.log");
  EXPECT_NE(log.find("--stage alpha --step 0"), std::string::npos) << log;
}

// A replay's step belongs to its stage: the labelling's 500th event does not carry over to the
// carving (which has fewer steps), and a link to a carving step opens it.
TEST(Viewer, AStepStaysWithItsReplay) {
  EXPECT_EQ(run_viewer_script("step-carry",
                              "stage propagation\nstep 500\nframes 2\nstage carving\n"
                              "frames 3\nlink\nquit\n",
                              "--example star --method paper"),
            0);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/step-carry.log");
  EXPECT_NE(log.find("--stage carving"), std::string::npos) << log;
  EXPECT_EQ(log.find("--stage carving --step"), std::string::npos) << log;
  EXPECT_EQ(run_viewer_script("step-link", "wait\nframes 3\nlink\nquit\n",
                              "--example star --method paper --stage carving --step 12"),
            0);
  const std::string linked = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/step-link.log");
  EXPECT_NE(linked.find("--stage carving --step 12"), std::string::npos) << linked;
}

// Side by side: `compare a,b` draws each method in a view of its own, one camera for both,
// with its verdict; compare off returns to one view; one method, or a misspelt one, is refused.
TEST(Viewer, ComparesMethodsSideBySide) {
  const std::string two = testing::output_path("viewer-compare-two.png"),
                    one = testing::output_path("viewer-compare-off.png");
  ASSERT_EQ(run_viewer_script("compare",
                              "example star\nwait\ncompare paper,boissonnat\nwait\nframes 3\n"
                              "screenshot " +
                                  two + "\ncompare off\nframes 3\nscreenshot " + one +
                                  "\ncompare paper,robsut\ncompare paper\nquit\n"),
            1);  // the last two commands are refused
  const render::Image both = render::read_png(two), single = render::read_png(one);
  // The curve's samples in both halves of the picture right of the panel (1280 x 720, the
  // panel about 360 wide): each view draws the whole star.
  const auto samples_in = [](const render::Image& image, int from, int to) {
    long count = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = from; x < to; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        if (p[1] > 100 && p[0] < 60 && p[2] < 60) ++count;  // the samples' green
      }
    }
    return count;
  };
  const int middle = (400 + both.width) / 2;
  EXPECT_GT(samples_in(both, 400, middle - 20), 200);
  EXPECT_GT(samples_in(both, middle + 20, both.width), 200);
  // One view again: one star's samples, where two views drew two stars' (dots of a fixed size).
  EXPECT_GT(samples_in(both, 400, both.width), 1.5 * samples_in(single, 400, single.width));
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/compare.log");
  EXPECT_NE(log.find("no method 'robsut' (did you mean 'robust'?)"), std::string::npos) << log;
}

// The colour-blind palette redraws the picture: the paper's red poles become vermillion.
TEST(Viewer, TheColourBlindPaletteRedrawsThePicture) {
  const std::string paper = testing::output_path("viewer-palette-paper.png"),
                    safe = testing::output_path("viewer-palette-safe.png"),
                    kept = testing::output_path("viewer-palette-kept.png");
  ASSERT_EQ(run_viewer_script("palette",
                              "example star\nwait\nstage poles\nframes 2\nscreenshot " + paper +
                                  "\npalette colour-blind\nframes 2\nscreenshot " + safe +
                                  "\nmethod paper\nwait\nstage poles\nframes 2\n"
                                  "screenshot " +
                                  kept + "\nlink\npalette pink\nquit\n"),
            1);  // the last command is refused: no such palette
  const scene::Color vermillion{0.835f, 0.369f, 0.0f};
  EXPECT_EQ(share_of_colour(render::read_png(paper), vermillion), 0.0);
  EXPECT_GT(share_of_colour(render::read_png(paper), scene::palette::pole), 0.0005);
  EXPECT_GT(share_of_colour(render::read_png(safe), vermillion), 0.0005);
  // A preference of the viewer: kept for the next reconstruction, and in the link to the view.
  EXPECT_GT(share_of_colour(render::read_png(kept), vermillion), 0.0005);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/palette.log");
  EXPECT_NE(log.find("--palette colour-blind"), std::string::npos) << log;
}

// A picture exported from the viewer is the view on screen: the cut-away and the neighbourhood
// go with it, and the layers are those of the stage just chosen, before a frame has drawn it.
TEST(Viewer, ExportedPicturesKeepTheCutAwayAndTheNeighbourhood) {
  const std::string whole = testing::output_path("viewer-export-whole.png"),
                    cut = testing::output_path("viewer-export-cut.png"),
                    near = testing::output_path("viewer-export-near.png");
  ASSERT_EQ(
      run_viewer_script("export-view", "example bumpy\nwait\nstage delaunay\nexport " + whole +
                                           " 700x600\nclip 0.5 30 60 0.06\nexport " + cut +
                                           " 700x600\nclip off\npick-sample 5\n"
                                           "neighbourhood on\nexport " +
                                           near + " 700x600\nquit\n"),
      0);
  // An exported picture has no panel: all of it is measured.
  const double whole_share = most_common_colour_share(render::read_png(whole), 0, 0);
  const double cut_share = most_common_colour_share(render::read_png(cut), 0, 0);
  const double near_share = most_common_colour_share(render::read_png(near), 0, 0);
  EXPECT_LT(cut_share, whole_share / 2) << "whole " << whole_share << ", cut " << cut_share;
  EXPECT_LT(near_share, whole_share / 2) << "whole " << whole_share << ", near " << near_share;
}

// Commands that do not apply to what is shown are refused in one line, not ignored.
TEST(Viewer, RefusesCommandsThatDoNotApplyToWhatIsShown) {
  const auto refused = [](const std::string& name, const std::string& script,
                          const std::string& why) {
    EXPECT_EQ(run_viewer_script(name, script + "\nquit\n"), 1) << script;
    const std::string log =
        testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/" + name + ".log");
    EXPECT_NE(log.find("sculpt-view: script: "), std::string::npos) << log;
    EXPECT_NE(log.find(why), std::string::npos) << log;
  };
  refused("refuse-clip-2d", "example star\nwait\nclip 0.5 0 0", "this is a curve");
  refused("refuse-edit-3d", "example sphere\nwait\nedit on", "this is a surface");
  refused("refuse-neighbourhood", "example sphere\nwait\nneighbourhood on", "pick a sample first");
  refused("refuse-step", "example star\nmethod crust\nwait\nstep 30", "no replay");
}

// Mistakes are named with what was meant: a stage name, the stages listed; the kind a script
// opens an example as; --frames on a bad file says what failed, not a script's step.
TEST(Viewer, AMistypedStageIsNamedAndTheKindCanBeChosen) {
  EXPECT_EQ(run_viewer_script("stage-typo", "example star\nwait\nstage delauny\nquit\n"), 1);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/stage-typo.log");
  EXPECT_NE(log.find("no stage 'delauny' (did you mean 'delaunay'?); the stages are samples, "),
            std::string::npos)
      << log;

  EXPECT_EQ(run_viewer_script("kind-bordered", "kind bordered\nexample star\nwait\nstats\nquit\n"),
            0);
  const std::string stats =
      testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/kind-bordered.log");
  EXPECT_NE(stats.find("\"kind\":\"bordered\""), std::string::npos) << stats;
  EXPECT_EQ(run_viewer_script("kind-wrong", "kind open\nquit\n"), 1);

  const std::string bad = testing::write_file("frames-bad.xyz", "not a point\n");
  const std::string log_path = testing::output_path("frames-bad.log");
  EXPECT_EQ(run("xvfb-run -a sh -c '" + std::string(SCULPT_VIEW_EXECUTABLE) + " " + bad +
                " --frames 2' >" + log_path + " 2>&1"),
            1);
  const std::string frames_log = testing::read_file(log_path);
  EXPECT_NE(frames_log.find("sculpt-view: error: "), std::string::npos) << frames_log;
  EXPECT_EQ(frames_log.find("script"), std::string::npos) << frames_log;
}

// The lines "stats: {...}" a script printed, in order.
std::vector<nlohmann::json> printed_statistics(const std::string& log) {
  std::vector<nlohmann::json> all;
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("stats: ", 0) == 0) all.push_back(nlohmann::json::parse(line.substr(7)));
  }
  return all;
}

// Pixels of the drawing area within 12 of a colour (0..1 channels).
std::size_t pixels_of(const render::Image& image, float r, float g, float b) {
  std::size_t count = 0;
  for (int y = 30; y < image.height; ++y) {
    for (int x = panel_width + 1; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      count += std::abs(p[0] - 255 * r) < 12 && std::abs(p[1] - 255 * g) < 12 &&
               std::abs(p[2] - 255 * b) < 12;
    }
  }
  return count;
}

// A file that fails leaves no blank picture: a red notice in the picture says what failed, and
// over an older picture, that it is the last one that worked.
TEST(Viewer, AFailureIsSaidInThePicture) {
  const std::string bad = testing::write_file("notice-bad.xyz", "not a point\n");
  for (const std::string before : {"", "example torus\nwait\n"}) {
    const std::string shot = testing::output_path("notice.png");
    EXPECT_EQ(
        run_viewer_script("notice", before + "open " + bad + "\nwait-idle\nframes 3\nscreenshot " +
                                        shot + "\nquit\n"),
        0);
    const render::Image image = render::read_png(shot);
    EXPECT_GT(pixels_of(image, 0.70f, 0.08f, 0.06f), 20000u) << before;  // the notice's red
  }
}

// In front of a class: 1024x768, text at 2x. Presenting, the panel's dark grey is gone and the
// picture takes the whole window, its legend in it; the picture scale makes the samples bigger.
TEST(Viewer, PresentationModeGivesThePictureTheWholeWindow) {
  const auto shot_of = [](const std::string& name, const std::string& commands) {
    const std::string shot = testing::output_path(name + ".png");
    EXPECT_EQ(
        run_viewer_script(
            name, "example star\nwait\n" + commands + "frames 3\nscreenshot " + shot + "\nquit\n",
            "--size 1024x768 --font-scale 2"),
        0);
    return render::read_png(shot);
  };
  // The share of the window's left 70% (below the menu bar) in the panel's grey.
  const auto panel_share = [](const render::Image& image) {
    const auto level = [](float c) { return int(std::lround(255 * c)); };
    const auto& panel = viewer::panel_colours::window;
    std::size_t grey = 0, all = 0;
    for (int y = 40; y < image.height; ++y) {
      for (int x = 0; x < image.width * 7 / 10; ++x, ++all) {
        const auto* p = image.pixel(x, y);
        grey += std::abs(p[0] - level(panel.r)) < 6 && std::abs(p[1] - level(panel.g)) < 6 &&
                std::abs(p[2] - level(panel.b)) < 6;
      }
    }
    return double(grey) / double(all);
  };
  // The samples' green anywhere in the window.
  const auto green = [](const render::Image& image) {
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const auto* p = image.pixel(x, y);
        count += std::abs(p[0] - 13) < 14 && std::abs(p[1] - 140) < 14 && std::abs(p[2] - 26) < 14;
      }
    }
    return count;
  };
  const render::Image plain = shot_of("present-off", "");
  const render::Image presenting = shot_of("present-on", "present on\n");
  const render::Image scaled = shot_of("present-scaled", "present on\npicture-scale 2\n");
  EXPECT_GT(panel_share(plain), 0.5);
  EXPECT_LT(panel_share(presenting), 0.02);
  EXPECT_GT(green(scaled), 2 * green(presenting));
  // F5 toggles it, as slide software does.
  EXPECT_LT(panel_share(shot_of("present-key", "key f5\n")), 0.02);
  EXPECT_EQ(run_viewer_script("present-bad", "picture-scale nan\nquit\n"), 1);
  // The command line that opens this view again opens it presenting.
  EXPECT_EQ(run_viewer_script("present-link",
                              "example star\nwait\npresent on\npicture-scale 2\nlink\nquit\n"),
            0);
  const std::string log = testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/present-link.log");
  EXPECT_NE(log.find("sculpt-view --example star --present --picture-scale 2"), std::string::npos)
      << log;
}

// The torus's outer seeds lie far off screen in every direction: gathered, one arrow for each
// sixteenth of the turn with its count, not a solid frame of arrows around the picture.
TEST(Viewer, OffScreenSeedsAreGatheredByDirection) {
  const std::string shot = testing::output_path("gathered-seeds.png");
  ASSERT_EQ(run_viewer_script(
                "gathered-seeds",
                "example torus\nwait\nstage seeds\nframes 3\nscreenshot " + shot + "\nquit\n"),
            0);
  const std::size_t magenta =
      pixels_of(render::read_png(shot), 200 / 255.0f, 40 / 255.0f, 160 / 255.0f);
  EXPECT_GT(magenta, 100u);
  EXPECT_LT(magenta, 16u * 900u);  // 16 arrows and their counts at most
}

// A lesson on undersampling: delete the samples of one of the star's valleys and the curve cuts
// across it; add one sample at the valley's bottom and the curve follows the valley again; drag
// it out, undo; save the edited points, which then reconstruct as they were shown.
TEST(Viewer, AScriptedLessonEditsSamplesAndEveryStageFollows) {
  const auto star = shapes::star(200);
  // Samples 12 to 28 lie in the valley around sample 20 (the star's arms alternate every 40).
  std::string script = "example star\nwait\nstats\n";
  for (int k = 28; k >= 12; --k) script += "delete-point " + std::to_string(k) + "\n";
  const std::string cut = testing::output_path("lesson-valley-cut.png"),
                    kept = testing::output_path("lesson-valley-kept.png"),
                    voronoi = testing::output_path("lesson-voronoi.png"),
                    saved = testing::output_path("lesson.xy");
  const Point<2> bottom = star.samples[20];
  script += "wait\nstats\nframes 2\nscreenshot " + cut + "\n";
  script += "add-point " + std::to_string(bottom[0]) + " " + std::to_string(bottom[1]) + "\n";
  script += "wait\nstats\nframes 2\nscreenshot " + kept + "\n";
  script += "stage voronoi\nframes 2\nscreenshot " + voronoi + "\n";
  script += "move-point 183 0.9 0.9\nwait\nstats\nundo\nwait\nstats\n";
  script += "stroke 0.02 -0.2 -0.2 0.2 0.2\nwait\nstats\nundo\nwait\n";
  script += "save-points " + saved + "\nquit\n";
  ASSERT_EQ(run_viewer_script("lesson", script), 0);
  const auto stats =
      printed_statistics(testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/lesson.log"));
  ASSERT_EQ(stats.size(), 6u);
  const auto edges = [&](int i) { return stats[i]["facets"].get<int>(); };
  EXPECT_EQ(stats[0]["samples"], 200);
  EXPECT_EQ(stats[1]["samples"], 183);  // 17 deleted
  EXPECT_EQ(edges(1), 183);             // still one closed curve, across the valley
  EXPECT_EQ(stats[2]["samples"], 184);
  EXPECT_EQ(edges(2), 184);  // the added sample is on the curve
  EXPECT_EQ(stats[2]["unused_samples"], 0);
  EXPECT_NE(stats[3], stats[2]);  // dragged out of the star: the curve changed
  // Undo gives back the points, and so the same curve (timings aside).
  for (const char* field : {"samples", "facets", "components", "carved_cells", "delaunay_cells"})
    EXPECT_EQ(stats[4][field], stats[2][field]) << field;
  // A stroke 0.57 long across the middle, samples 0.02 of the box diagonal (about 3.6) apart:
  // about 9 samples.
  EXPECT_GE(stats[5]["samples"].get<int>(), 184 + 7);
  EXPECT_LE(stats[5]["samples"].get<int>(), 184 + 11);
  // The true curve is drawn wider than the result, a halo around it where they agree. Cut
  // across, the valley's true curve is seen whole besides; followed, it is covered again.
  const auto truth = scene::palette::true_curve;
  const std::size_t uncovered_cut = pixels_of(render::read_png(cut), truth.r, truth.g, truth.b);
  const std::size_t uncovered_kept = pixels_of(render::read_png(kept), truth.r, truth.g, truth.b);
  EXPECT_GT(uncovered_cut, uncovered_kept + 200)
      << "cut " << uncovered_cut << ", kept " << uncovered_kept;
  EXPECT_GT(drawn_pixels(render::read_png(voronoi)), drawn_pixels(render::read_png(kept)));
  // The saved points are the ones shown after the undo: 184 of them.
  const auto reloaded = frontend::load_input(saved, "", 0);
  ASSERT_EQ(reloaded.dimension(), 2);
  EXPECT_EQ(std::get<0>(reloaded.points).size(), 184u);
  std::cout << "lesson: uncovered true-curve pixels " << uncovered_cut << " cut, " << uncovered_kept
            << " followed\n";
}

// Edits that cannot be made say why, in one line, and fail the script.
TEST(Viewer, AnEditThatCannotBeMadeIsOneLineAndAFailure) {
  for (const auto& [name, script] : std::vector<std::pair<std::string, std::string>>{
           {"edit-out-of-range", "example star\nwait\ndelete-point 999\nquit\n"},
           {"edit-repeated", "example star\nwait\nadd-point 0 0\nwait\nadd-point 0 0\nquit\n"},
           {"edit-nothing-to-undo", "example star\nwait\nundo\nquit\n"},
           {"edit-3d", "example sphere\nwait\nadd-point 0 0\nquit\n"},
           {"edit-malformed", "example star\nwait\nmove-point 3 x 1\nquit\n"},
           {"edit-no-layer", "example star\nwait\nlayer nonexistent off\nquit\n"}}) {
    EXPECT_EQ(run_viewer_script(name, script), 1) << name;
    const std::string log =
        testing::read_file(std::string(SCULPT_TEST_OUTPUT) + "/" + name + ".log");
    EXPECT_NE(log.find("sculpt-view: script: "), std::string::npos) << name << ": " << log;
  }
}

// The star's first labelling events are convex seeds far out by the box corners. Following,
// the camera pans until the pole just labelled is in view; not following, it stays on the star
// and an arrow at the edge points to the pole. The seeds stage points to its seeds the same way.
TEST(Viewer, TheReplayFollowsThePoleJustLabelled) {
  const std::string followed = testing::output_path("replay-followed.png"),
                    still = testing::output_path("replay-still.png"),
                    seeds = testing::output_path("seeds-arrows.png");
  ASSERT_EQ(
      run_viewer_script("follow",
                        "example star\nwait\nstage propagation\nstep 1\nwait\n"
                        "frames 2\nscreenshot " +
                            followed + "\nfollow off\nkey r\nstep 1\nframes 2\nscreenshot " +
                            still + "\nstage seeds\nframes 2\nscreenshot " + seeds + "\nquit\n"),
      0);
  const auto yellow = scene::palette::current_pole;
  const float arrow[3] = {200 / 255.0f, 40 / 255.0f, 160 / 255.0f};
  const auto followed_image = render::read_png(followed), still_image = render::read_png(still);
  EXPECT_GT(pixels_of(followed_image, yellow.r, yellow.g, yellow.b), 20u);
  EXPECT_EQ(pixels_of(still_image, yellow.r, yellow.g, yellow.b), 0u);
  EXPECT_GT(pixels_of(still_image, arrow[0], arrow[1], arrow[2]), 50u);
  EXPECT_GT(pixels_of(render::read_png(seeds), arrow[0], arrow[1], arrow[2]), 500u);
}

// The neighbourhood of a picked sample: its cell, its balls and the cells that reach it, the
// camera fitted to them; polar balls drawn a few at a time with a stride.
TEST(Viewer, ShowsTheNeighbourhoodOfAPickedSampleAndPolarBallsWithAStride) {
  const std::string near = testing::output_path("viewer-neighbourhood.png"),
                    balls = testing::output_path("viewer-polar-balls.png");
  ASSERT_EQ(run_viewer_script("neighbourhood",
                              "example bumpy\nwait\nstage delaunay\npick-sample 100\n"
                              "neighbourhood on\nframes 2\nscreenshot " +
                                  near +
                                  "\nneighbourhood off\npick-sample -1\nstage poles\n"
                                  "polar-balls 600\nframes 2\nscreenshot " +
                                  balls + "\npolar-balls off\npolar-balls x\nquit\n"),
            1);  // the last command is refused
  const double near_share = most_common_colour_share(render::read_png(near));
  EXPECT_LT(near_share, 0.2);
  EXPECT_GT(drawn_pixels(render::read_png(near)), 5000u);
  const auto ball = scene::palette::polar_ball_3d;
  EXPECT_EQ(pixels_of(render::read_png(balls), ball.r, ball.g, ball.b), 0u);  // translucent
  EXPECT_GT(drawn_pixels(render::read_png(balls)), 20000u);
}

// The viewer saves the replay, or a sweep of the stages, as an animated WebP.
TEST(Viewer, ExportsTheReplayAsAnAnimation) {
  const std::string replay = testing::output_path("viewer-replay.webp");
  ASSERT_EQ(run_viewer_script("animation",
                              "example star\nwait\nstage propagation\n"
                              "export-animation " +
                                  replay + " 300x200 8\nexport-animation " +
                                  testing::output_path("not-webp.png") + "\nquit\n"),
            1);  // the second is refused: an animation is a .webp
  const std::string bytes = testing::read_file(replay);
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "RIFF");
  EXPECT_EQ(bytes.substr(8, 4), "WEBP");
  EXPECT_NE(bytes.find("ANMF"), std::string::npos);
}

// Runs a lesson shipped in examples/lessons with its pictures and saved points written into a
// folder of the test's own (not the current one); returns how many pictures it took, or -1 if
// the viewer failed.
int run_lesson(const std::string& name) {
  std::string script =
      testing::read_file(std::string(SCULPT_SOURCE_DIR) + "/examples/lessons/" + name + ".script");
  EXPECT_FALSE(script.empty()) << name;
  const std::string folder = std::string(SCULPT_TEST_OUTPUT) + "/lesson-" + name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  for (const std::string verb : {"screenshot ", "save-points "}) {
    for (auto at = script.find(verb); at != std::string::npos; at = script.find(verb, at + 1))
      script.insert(at + verb.size(), folder + "/");
  }
  if (run_viewer_script("lesson-" + name, script) != 0) return -1;
  int pictures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    pictures += entry.path().extension() == ".png";
  return pictures;
}

// The lesson on undersampling runs through, picture by picture, and saves the points it drew.
TEST(Viewer, TheShippedLessonRuns) {
  EXPECT_EQ(run_lesson("undersampling"), 8);
  EXPECT_TRUE(
      std::filesystem::exists(std::string(SCULPT_TEST_OUTPUT) + "/lesson-undersampling/lesson.xy"));
}

// The lesson on comparing methods runs too, side by side included (what its narration claims
// of each method is tested in lesson_claims_test.cpp).
TEST(Viewer, TheComparingLessonRuns) {
  EXPECT_EQ(run_lesson("comparing"), 8);
}

// Another model is framed afresh; another method on the same points keeps the camera.
TEST(Viewer, FitsTheCameraToEveryNewModel) {
  const std::string blob = testing::output_path("new-model-fitted.png"),
                    crust = testing::output_path("same-model-other-method.png");
  ASSERT_EQ(run_viewer_script("new-model",
                              "example star\nwait\ncamera zoom 0.05\n"
                              "example blob\nwait\nframes 2\nscreenshot " +
                                  blob +
                                  "\ncamera zoom 0.05\nmethod crust\nwait\n"
                                  "frames 2\nscreenshot " +
                                  crust + "\nquit\n"),
            0);
  const auto green = scene::palette::sample;
  const std::size_t fitted = pixels_of(render::read_png(blob), green.r, green.g, green.b);
  const std::size_t kept = pixels_of(render::read_png(crust), green.r, green.g, green.b);
  EXPECT_GT(fitted, 1500u);     // the blob's 150 samples, all in view
  EXPECT_LT(kept, fitted / 4);  // zoomed in 20 times, and kept so across the method switch
}

TEST(Viewer, WithoutADisplayItNamesTheHeadlessCommand) {
  const std::string log = testing::output_path("no-display.log");
  const int code = run("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SCULPT_VIEW_EXECUTABLE) +
                       " >" + log + " 2>&1");
  EXPECT_EQ(code, 1);
  EXPECT_NE(testing::read_file(log).find("sculpt render"), std::string::npos)
      << testing::read_file(log);
}

}  // namespace
}  // namespace sculpt
