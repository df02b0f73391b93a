// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in examples: their names and descriptions, and the shapes behind each name.
#include <stdexcept>

#include "shapes.hpp"

namespace sculpt::shapes {

const std::vector<Example>& examples() {
  static const std::vector<Example> list = {
      {"circle", 2, "64 samples on a circle", false},
      {"star", 2, "a five-armed star, 200 samples", false},
      {"blob", 2, "a smooth blob, 150 samples", false},
      {"blob-dense", 2, "the same blob, 600 samples", false},
      {"nested", 2, "two nested circles (an annulus), 120 + 60 samples", false},
      {"nonuniform", 2, "an ellipse sampled 9:1 non-uniformly, 200 samples", false},
      {"arc", 2, "an open three-quarter circle, 60 samples (bordered)", true},
      {"wavy-arc", 2, "340 degrees of the blob's outline: an open curve nearly closed (bordered)",
       true},
      {"spiral", 2, "an open spiral of 2.5 turns, 179 samples (bordered)", true},
      {"strokes", 2, "two wavy open strokes side by side, 41 samples each (bordered)", true},
      {"bracket", 2,
       "a bracket with sharp corners, a slot narrower than the spacing and a noisy end, 160 "
       "samples: the methods differ",
       false},
      {"sphere", 3, "2000 samples on a sphere", false},
      {"torus", 3, "4000 random samples on a torus (genus 1)", false},
      {"bumpy", 3, "a sphere with dents and bumps, 6000 samples", false},
      {"saddle", 3, "the saddle z = x^2 - y^2, 40 x 40 jittered samples (bordered)", true},
      {"monkey-saddle", 3, "the monkey saddle z = x^3 - 3xy^2, 40 x 40 samples (bordered)", true},
      {"hemisphere", 3, "half a sphere, 3000 samples (bordered)", true},
      {"open-cylinder", 3, "a tube open at both ends, about 3000 jittered samples (bordered)",
       true},
      {"wavy-annulus", 3, "a wavy ring: a sheet with an outer and an inner border (bordered)",
       true},
      {"holey-sphere", 3, "a sphere with three round holes of different sizes (bordered)", true},
      {"torso", 3, "a smooth torso-like blob, 8000 samples", false},
      {"torus-knot", 3, "a tube around a (2,3) torus knot, 12000 samples", false},
      {"three-holes", 3, "three overlapping tori: a solid with three holes, ~10000 samples", false},
      {"bumpy-nonuniform", 3, "the bumpy sphere thinned 3:1 on its +x side", false},
      {"drilled-block", 3,
       "a block with a hole: sharp edges, a sparse back and a noisy end, 4000 samples: the "
       "methods differ",
       false},
  };
  return list;
}

const Example* find_example(const std::string& name) {
  for (const auto& example : examples()) {
    if (example.name == name) return &example;
  }
  return nullptr;
}

std::vector<Point<2>> example_points_2(const std::string& name) {
  if (name == "circle") return circle(64).samples;
  if (name == "star") return star(200).samples;
  if (name == "blob") return blob(150).samples;
  if (name == "blob-dense") return blob(600).samples;
  if (name == "nested") return nested_circles(120, 60).samples;
  if (name == "nonuniform") return nonuniform_ellipse(200).samples;
  if (name == "arc") return open_arc(60).samples;
  if (name == "wavy-arc") return wavy_arc(340).samples;
  if (name == "spiral") return spiral().samples;
  if (name == "strokes") return two_strokes().samples;
  if (name == "bracket") return bracket(160).samples;
  throw std::invalid_argument("no 2D example named '" + name + "'");
}

Sampled_curve example_curve_2(const std::string& name) {
  constexpr int dense = 10;
  if (name == "circle") return circle(64 * dense);
  if (name == "star") return star(200 * dense);
  if (name == "blob" || name == "blob-dense") return blob(600 * dense);
  if (name == "nested") return nested_circles(120 * dense, 60 * dense);
  if (name == "nonuniform") return nonuniform_ellipse(200 * dense);
  if (name == "arc") return open_arc(60 * dense);
  if (name == "wavy-arc") return wavy_arc(340, 150 * dense);
  if (name == "spiral") return spiral(2.5, 0.2 / dense);
  if (name == "strokes") return two_strokes(0.5, 40 * dense + 1);
  if (name == "bracket") return bracket(160 * dense, /*noisy=*/false);
  throw std::invalid_argument("no 2D example named '" + name + "'");
}

std::vector<Point<3>> example_points_3(const std::string& name) {
  if (name == "sphere") return sphere(2000);
  if (name == "torus") return torus(4000);
  if (name == "bumpy") return bumpy_sphere(6000);
  if (name == "saddle") return saddle(40);
  if (name == "monkey-saddle") return monkey_saddle(40);
  if (name == "hemisphere") return hemisphere(3000);
  if (name == "open-cylinder") return open_cylinder(3000);
  if (name == "wavy-annulus") return wavy_annulus(3000);
  if (name == "holey-sphere") return sphere_with_holes(4000);
  if (name == "torso") return torso(8000);
  if (name == "torus-knot") return torus_knot_tube(12000);
  if (name == "three-holes") return three_holes(10000);
  if (name == "bumpy-nonuniform") return thinned_on_one_side(bumpy_sphere(6000), 3);
  if (name == "drilled-block") return drilled_block(4000);
  throw std::invalid_argument("no 3D example named '" + name + "'");
}

}  // namespace sculpt::shapes
