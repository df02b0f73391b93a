// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/colours.hpp"

#include <utility>

#include "scene/palette.hpp"

namespace sculpt::scene {
namespace {

// The paper's colour of a layer and its colour-blind-safe counterpart. Built around the
// Okabe-Ito colours for what every lesson shows (samples black, inner poles vermillion, outer
// poles sky blue, Voronoi edges bluish green, Delaunay edges grey, the solid light yellow); the
// rest chosen, by a search over the pairs of layers that share a picture, to keep every such
// pair at least 25 apart in CIELAB as seen with normal vision, deuteranopia and protanopia.
struct Counterpart {
  Color paper, safe;
};

const std::vector<Counterpart>& counterparts() {
  namespace p = palette;
  static const std::vector<Counterpart> table = {
      {p::sample, {0.000f, 0.000f, 0.000f}},
      {p::curve, {0.000f, 0.447f, 0.698f}},
      {p::pole, {0.835f, 0.369f, 0.000f}},  // the inner poles' colour too
      {p::outer_pole_2d, {0.337f, 0.706f, 0.914f}},
      {p::outer_pole_3d, {0.337f, 0.706f, 0.914f}},
      {p::delaunay_edge, {0.600f, 0.600f, 0.600f}},
      {p::voronoi_edge, {0.000f, 0.620f, 0.451f}},
      {p::solid, {0.940f, 0.890f, 0.550f}},
      {p::sculpted_away, {0.500f, 0.600f, 0.500f}},
      {p::just_removed, {0.835f, 0.369f, 0.000f}},
      {p::carving_circle, {0.950f, 0.800f, 0.000f}},
      {p::surface, {0.800f, 0.800f, 0.800f}},
      {p::section_outside, {0.930f, 0.930f, 0.930f}},
      {p::section_edge, {0.400f, 0.400f, 0.550f}},
      {p::cut_cell_edge, {0.500f, 0.800f, 1.000f}},  // the wireframe's colour too
      {p::polar_ball, {0.000f, 0.500f, 1.000f}},
      {p::polar_ball_3d, {1.000f, 0.700f, 0.000f}},
      {p::inner_ball, {0.000f, 0.500f, 1.000f}},
      {p::outer_ball, {0.100f, 0.000f, 0.200f}},
      {p::convex_pole, {0.700f, 0.800f, 0.700f}},
      {p::unlabelled_pole, {0.400f, 0.300f, 0.600f}},
      {p::picked_sample, {0.000f, 0.000f, 1.000f}},
      {p::unused_sample, {0.800f, 0.500f, 0.300f}},
      {p::inscribed_cube, {0.000f, 0.000f, 0.400f}},
      {p::focus_cell, {0.400f, 0.100f, 0.000f}},
      {p::focus_ball, {0.100f, 0.100f, 0.700f}},
      {p::picked_pole, {0.000f, 0.300f, 0.300f}},
      {p::source_cube, {1.000f, 0.700f, 0.500f}},
      {p::source_ball, {0.700f, 0.400f, 0.300f}},
      {p::current_pole, {0.800f, 0.700f, 0.700f}},
      {p::non_manifold, {0.700f, 0.600f, 1.000f}},
      {p::border, {0.100f, 0.800f, 1.000f}},
      {p::opening, {1.000f, 0.700f, 0.000f}},
      {p::contradicted_pole, {0.000f, 0.300f, 0.500f}},
      {p::undersampled, {0.700f, 0.700f, 0.700f}},
      {p::removed_outlier, {0.835f, 0.369f, 0.000f}},  // beside black samples, grey as given
  };
  return table;
}

bool same_hue(const Color& a, const Color& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

}  // namespace

const char* colours_name(Colours colours) {
  return colours == Colours::colour_blind ? "colour-blind" : "paper";
}

const std::vector<std::string>& colours_names() {
  static const std::vector<std::string> names = {"paper", "colour-blind"};
  return names;
}

bool parse_colours(const std::string& name, Colours& colours) {
  if (name == "paper")
    colours = Colours::paper;
  else if (name == "colour-blind" || name == "color-blind")
    colours = Colours::colour_blind;
  else
    return false;
  return true;
}

void recolour(Scene& scene, Colours colours) {
  if (colours == Colours::paper) return;
  for (auto& layer : scene.layers) {
    for (const auto& [paper, safe] : counterparts()) {
      if (!same_hue(layer.color, paper)) continue;
      layer.color = {safe.r, safe.g, safe.b, layer.color.a};
      break;
    }
  }
}

}  // namespace sculpt::scene
