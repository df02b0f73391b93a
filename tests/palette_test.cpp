// SPDX-License-Identifier: GPL-3.0-or-later
// Every layer a stage shows has a colour of its own, told apart at a glance: for every method,
// in 2D and 3D, every stage, with and without a picked sample or pole, mid-replay. Colours are
// compared as people see them (CIELAB distance), not as RGB numbers: a dark and a light green
// are far apart in RGB and still both "green" on a projector.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "scene/scene.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

struct Lab {
  double l, a, b;
};

Lab to_lab(const scene::Color& c) {
  const auto linear = [](double u) {
    return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4);
  };
  const double r = linear(c.r), g = linear(c.g), b = linear(c.b);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

// How a colour looks with a red-green deficiency: Machado, Oliveira and Fernandes (2009), full
// severity, applied to linear RGB.
enum class Vision { normal, deuteranopia, protanopia };

scene::Color as_seen(const scene::Color& c, Vision vision) {
  if (vision == Vision::normal) return c;
  static constexpr double deuteranopia[3][3] = {{0.367322, 0.860646, -0.227968},
                                                {0.280085, 0.672501, 0.047413},
                                                {-0.011820, 0.042940, 0.968881}};
  static constexpr double protanopia[3][3] = {{0.152286, 1.052583, -0.204868},
                                              {0.114503, 0.786281, 0.099216},
                                              {-0.003882, -0.048116, 1.051998}};
  const auto& m = vision == Vision::deuteranopia ? deuteranopia : protanopia;
  const auto linear = [](double u) {
    return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4);
  };
  const auto encoded = [](double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u <= 0.0031308 ? 12.92 * u : 1.055 * std::pow(u, 1 / 2.4) - 0.055;
  };
  const double rgb[3] = {linear(c.r), linear(c.g), linear(c.b)};
  float out[3];
  for (int i = 0; i < 3; ++i)
    out[i] = float(encoded(m[i][0] * rgb[0] + m[i][1] * rgb[1] + m[i][2] * rgb[2]));
  return {out[0], out[1], out[2], c.a};
}

const char* vision_name(Vision vision) {
  return vision == Vision::normal         ? ""
         : vision == Vision::deuteranopia ? " (deuteranopia)"
                                          : " (protanopia)";
}

double perceived_distance(const scene::Color& p, const scene::Color& q) {
  const Lab a = to_lab(p), b = to_lab(q);
  return std::sqrt((a.l - b.l) * (a.l - b.l) + (a.a - b.a) * (a.a - b.a) +
                   (a.b - b.b) * (a.b - b.b));
}

// CIELAB distance of 25: two colours a class names differently (about 2.3 is the smallest
// difference anyone notices; the paper's green samples and green Voronoi edges were 18 apart).
constexpr double least_distance = 25;

// The pairs of layers of one picture whose colours are too close, as readable lines.
std::vector<std::string> colour_clashes(const scene::Scene& scene, const std::string& where,
                                        Vision vision = Vision::normal) {
  std::vector<std::string> clashes;
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.layers.size(); ++j) {
      const auto& p = scene.layers[i];
      const auto& q = scene.layers[j];
      if (p.positions.empty() || q.positions.empty()) continue;
      // A part of a layer drawn apart (Layer::part_of: the step's corners) is in its colour.
      const bool part = q.part_of == p.id || p.part_of == q.id;
      if (part && p.color.r == q.color.r && p.color.g == q.color.g && p.color.b == q.color.b)
        continue;
      const double d = perceived_distance(as_seen(p.color, vision), as_seen(q.color, vision));
      if (d < least_distance) {
        std::ostringstream line;
        line << where << vision_name(vision) << ": " << p.id << " and " << q.id << " are " << d
             << " apart";
        clashes.push_back(line.str());
      }
    }
  }
  return clashes;
}

// The colour-blind scheme is checked as seen with each vision; the paper's with normal vision
// only (its red and green are the paper's, and collapse to olive under deuteranopia).
std::vector<Vision> visions(bool colour_blind) {
  if (!colour_blind) return {Vision::normal};
  return {Vision::normal, Vision::deuteranopia, Vision::protanopia};
}

template <int D>
void check_every_stage(const std::vector<Point<D>>& points, Surface_kind kind,
                       std::set<std::string>& clashes, int& pictures, bool colour_blind = false) {
  for (Method method : testing::methods_in(D)) {
    const std::string name = to_string(method);
    Options options = testing::with_method(method);
    options.kind = kind;
    options.keep_triangulations = true;
    const auto r = reconstruct(points, options);
    const int events = static_cast<int>(r.propagation.events.size());
    for (scene::Stage stage : scene::stages_of(options.method, D)) {
      std::vector<scene::Request> requests(D == 3 ? 5 : 4);
      requests[1].focus_sample = 0;  // a picked sample: its cell, poles, balls, cubes
      requests[2].focus_pole = r.poles.poles.empty() ? -1 : 0;
      requests[3].step = events / 2;  // mid-replay: the pole just labelled and its source
      if (D == 3) requests[4].sectioned = true;  // in section, the balls as circles
      // Every layer the stage can draw, polar balls and samples included (3D draws them on
      // shaded stages only when asked).
      for (auto& request : requests) {
        request.stage = stage;
        request.colour_blind = colour_blind;
        request.layers = scene::layer_ids(scene::build_scene(r, request));
        request.layers.push_back("polar-balls");
        request.layers.push_back("samples");
      }
      for (const auto& request : requests) {
        const auto scene = scene::build_scene(r, request);
        ++pictures;
        for (Vision vision : visions(colour_blind)) {
          for (const auto& clash : colour_clashes(
                   scene,
                   std::string(name) + " " + std::to_string(D) + "D " + scene::stage_id(stage),
                   vision))
            clashes.insert(clash);
        }
      }
    }
  }
}

class Palette : public ::testing::TestWithParam<bool> {};

// Every scheme, every method, every stage: every pair of layers one picture shows stays apart
// (the colour-blind scheme as seen with deuteranopia and protanopia too).
TEST_P(Palette, EveryLayerOfAStageHasAColourOfItsOwn) {
  const bool colour_blind = GetParam();
  std::set<std::string> clashes;
  int pictures = 0;
  check_every_stage<2>(shapes::star(80).samples, Surface_kind::closed, clashes, pictures,
                       colour_blind);
  check_every_stage<2>(shapes::open_arc(40).samples, Surface_kind::bordered, clashes, pictures,
                       colour_blind);
  check_every_stage<3>(shapes::bumpy_sphere(800), Surface_kind::closed, clashes, pictures,
                       colour_blind);
  // A bordered surface: its border edges beside the polar balls and poles.
  check_every_stage<3>(shapes::hemisphere(600), Surface_kind::bordered, clashes, pictures,
                       colour_blind);
  // A result that leaves samples off marks them, beside everything else the surface shows.
  Options tiny_alpha;
  tiny_alpha.method = Method::alpha_shape;
  tiny_alpha.alpha = 0.05;
  scene::Request surface;
  surface.layers = {"surface", "samples", "unused-samples"};
  surface.colour_blind = colour_blind;
  const auto left_off = scene::build_scene(reconstruct(shapes::sphere(400), tiny_alpha), surface);
  ASSERT_EQ(left_off.layers.size(), 3u);
  for (Vision vision : visions(colour_blind)) {
    for (const auto& clash : colour_clashes(left_off, "alpha-shape with samples left off", vision))
      clashes.insert(clash);
  }
  std::string all;
  for (const auto& clash : clashes) all += clash + "\n";
  EXPECT_TRUE(clashes.empty()) << clashes.size() << " clashes in " << pictures << " pictures:\n"
                               << all;
  EXPECT_GT(pictures, 100);
}

INSTANTIATE_TEST_SUITE_P(Schemes, Palette, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "colour_blind" : "paper";
                         });

// The simulation itself: the paper's red and green collapse under deuteranopia, black and white
// do not.
TEST(ColourVision, ThePapersRedAndGreenCollapseUnderDeuteranopia) {
  const scene::Color red{0.85f, 0.10f, 0.10f}, green{0.05f, 0.55f, 0.10f};
  EXPECT_GT(perceived_distance(red, green), 60);
  EXPECT_LT(
      perceived_distance(as_seen(red, Vision::deuteranopia), as_seen(green, Vision::deuteranopia)),
      least_distance);
  EXPECT_NEAR(perceived_distance(as_seen({1, 1, 1}, Vision::protanopia),
                                 as_seen({0, 0, 0}, Vision::protanopia)),
              100, 1);
}

// The colour test itself tells the paper's near-misses apart from distinct colours.
TEST(PaletteDistance, ThePerceivedDistanceSeparatesCloseHuesFromDistinctOnes) {
  EXPECT_LT(perceived_distance({0.05f, 0.55f, 0.10f}, {0.30f, 0.75f, 0.30f}), least_distance);
  EXPECT_GT(perceived_distance({0.85f, 0.10f, 0.10f}, {0.20f, 0.35f, 0.90f}), least_distance);
  EXPECT_NEAR(perceived_distance({1, 1, 1}, {0, 0, 0}), 100, 0.5);
}

}  // namespace
}  // namespace sculpt
