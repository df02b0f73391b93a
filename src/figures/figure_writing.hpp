// SPDX-License-Identifier: GPL-3.0-or-later
// How the paper's figures (method_figures.cpp, result_figures.cpp) are written down: a panel's
// shot, varied (bordered, zoomed, seen from below, by a peer), and what its text claims.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "paper_figures.hpp"

namespace sculpt::figures::writing {

using frontend::Shot;

// A shot of `input` ("example:NAME" or "cgal:FILE.off") at `stage`.
inline Shot shot(const std::string& input, const char* stage) {
  Shot s;
  s.method = to_string(Method::paper);  // the paper's figures show the paper's algorithm
  if (input.rfind("example:", 0) == 0) {
    s.example = input.substr(8);
  } else {
    s.input = input;  // resolved when the CGAL meshes are unpacked
  }
  s.stage = stage;
  return s;
}

inline Shot bordered(Shot s, double box_factor = sculpt::Options{}.box_factor) {
  s.bordered = true;
  s.box_factor = box_factor;
  return s;
}

// A bordered example reconstructed as if closed: what the closed algorithm does to a sheet.
inline Shot closed(Shot s) {
  s.closed = true;
  return s;
}

inline Shot with_layers(Shot s, std::vector<std::string> layers) {
  s.layers = std::move(layers);
  return s;
}

inline Shot zoomed(Shot s, float zoom) {
  s.zoom = zoom;
  s.wireframe = true;
  return s;
}

// Looking into a hemisphere's opening (its rim lies in the plane z = 0, the dome towards +z).
inline Shot from_below(Shot s) {
  s.yaw = 3.14159265f;
  s.pitch = 0.45f;
  return s;
}

inline Shot wire(Shot s) {
  s.wireframe = true;
  return s;
}

// The same input by one of the peers the paper compares with.
inline Shot with_method(Shot s, Method method) {
  s.method = to_string(method);
  return s;
}

// A panel's claim, asserted by tests/figures_test.cpp.
inline Claim closed_manifold_claim(long components, long samples_left_off_at_most) {
  Claim claim;
  claim.asserted = true;
  claim.closed_manifold = true;
  claim.components = components;
  claim.samples_left_off = {0, samples_left_off_at_most};
  return claim;
}

// Exactly the counts the text gives: a text whose numbers drift from the result fails its test.
inline Claim defects_claim(long non_manifold_edges, long samples_left_off, long components) {
  Claim claim;
  claim.asserted = true;
  claim.non_manifold_edges = {non_manifold_edges, non_manifold_edges};
  claim.samples_left_off = {samples_left_off, samples_left_off};
  claim.components = components;
  return claim;
}

inline Claim border_claim(long loops, long edges_at_least, long edges_at_most) {
  Claim claim;
  claim.asserted = true;
  claim.border_loops = loops;
  claim.border_edges = {edges_at_least, edges_at_most};
  return claim;
}

inline void claim(Figure& figure, const std::string& suffix, Claim claim) {
  for (auto& image : figure.images) {
    if (image.suffix == suffix) {
      image.claim = claim;
      return;
    }
  }
  throw std::logic_error(figure.id + " has no panel " + suffix);
}

// The figures of the method (the paper's sections 2-3): Figs. 1-8.
void add_method_figures(std::vector<Figure>& f);
// The figures of the results (section 4 on): Figs. 9-15.
void add_result_figures(std::vector<Figure>& f);

}  // namespace sculpt::figures::writing
