// SPDX-License-Identifier: GPL-3.0-or-later
// Sampled shapes with known answers: the built-in examples of the command line and the viewer,
// and the ground truth of the tests. Every generator is deterministic (fixed seeds).
#pragma once

#include <functional>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt::shapes {

// A sampled closed or open curve: samples in order along each curve, and the edges joining
// consecutive samples (the ground-truth polygon).
struct Sampled_curve {
  std::vector<Point<2>> samples;
  std::vector<Facet<2>> edges;  // counterclockwise around the region a closed curve bounds
};

// A closed plane curve given by a parametrisation t in [0, 1), sampled by arc length with the
// given relative density (1 = uniform; larger = denser there).
Sampled_curve sample_closed_curve(const std::function<Point<2>(double)>& curve, int samples,
                                  const std::function<double(double)>& density = {});

Sampled_curve circle(int samples);
Sampled_curve star(int samples, int arms = 5, double depth = 0.3);
Sampled_curve blob(int samples);
Sampled_curve nested_circles(int outer_samples, int inner_samples);  // an annulus' two borders
Sampled_curve nonuniform_ellipse(int samples, double ratio = 9.0);   // density ratio max/min
Sampled_curve open_arc(int samples);  // a three-quarter circle: two end points
// An open plane curve t in [0, 1], sampled by arc length from end to end (both ends sampled).
Sampled_curve sample_open_curve(const std::function<Point<2>(double)>& curve, int samples);
// The part of the blob's wavy outline from angle 0 to `degrees`, as densely sampled as
// blob(samples_per_turn): an open arc of any span up to nearly closed.
Sampled_curve wavy_arc(double degrees, int samples_per_turn = 150);
// An Archimedean spiral of `turns` turns, its arms one unit apart, samples `spacing` apart.
Sampled_curve spiral(double turns = 2.5, double spacing = 0.2);
// Two wavy open strokes side by side, `gap` apart, samples 0.05 apart (41 to a stroke).
Sampled_curve two_strokes(double gap = 0.5, int samples_per_stroke = 41);
// Samples along a drawn polyline, `spacing` apart by arc length, both ends included: how the
// viewer turns a stroke of the mouse into samples of a chosen density.
// At most `most` samples: a finer spacing is widened to fit.
std::vector<Point<2>> resample_polyline(const std::vector<Point<2>>& polyline, double spacing,
                                        std::size_t most = 10000);

// Surfaces: samples only.
std::vector<Point<3>> sphere(int samples);
std::vector<Point<3>> torus(int samples, double major = 1.0, double minor = 0.4, unsigned seed = 1);
std::vector<Point<3>> bumpy_sphere(int samples);  // a sphere with six dents and bumps
// The unit sphere as a scanner sees it: random samples, each moved off the sphere by Gaussian
// noise of standard deviation `noise` times the samples' mean spacing.
std::vector<Point<3>> noisy_sphere(int samples, double noise, unsigned seed = 1);
std::vector<Point<3>> saddle(int samples_per_side);  // z = x^2 - y^2 over [-1, 1]^2, jittered
std::vector<Point<3>> monkey_saddle(int samples_per_side);  // z = 0.35 (x^3 - 3 x y^2), jittered
std::vector<Point<3>> hemisphere(int samples);     // the upper half of a sphere: one border
std::vector<Point<3>> open_cylinder(int samples);  // radius 1, height 3: two borders
std::vector<Point<3>> wavy_annulus(int samples);   // radii 0.5 to 1, wavy: two borders
std::vector<Point<3>> sphere_with_holes(
    int samples);  // the unit sphere, three holes: three borders
std::vector<Point<3>> torus_knot_tube(int samples,
                                      unsigned seed = 3);  // a tube around a (2,3) knot
std::vector<Point<3>> three_holes(int samples,
                                  unsigned seed = 5);  // three overlapping tori: genus 3
std::vector<Point<3>> torso(int samples);              // a smooth torso-like blob with shoulders
// Made for comparing methods (hard_parts.cpp): sharp corners, a part narrower than the
// sampling, a noisy side and (3D) a sparse side, where the methods visibly differ.
Sampled_curve bracket(int samples, bool noisy = true);  // a bracket with a tooth and a slot
std::vector<Point<3>> drilled_block(int samples, unsigned seed = 11);  // a block with a hole
// Keeps every sample with x < 0 and one in `ratio` of the others: a non-uniform resampling.
std::vector<Point<3>> thinned_on_one_side(const std::vector<Point<3>>& points, int ratio);

// Built-in examples by name, for `sculpt reconstruct --example NAME` and the viewer.
struct Example {
  std::string name;
  int dimension;
  std::string description;
  bool bordered;
};
const std::vector<Example>& examples();
const Example* find_example(const std::string& name);  // nullptr if there is none
// Throws std::invalid_argument for an unknown name.
std::vector<Point<2>> example_points_2(const std::string& name);
// The curve a 2D example's samples lie on, drawn ten times as densely: the ground truth a
// reconstruction of those samples (or of edited ones) is compared with by eye.
Sampled_curve example_curve_2(const std::string& name);
std::vector<Point<3>> example_points_3(const std::string& name);

}  // namespace sculpt::shapes
