// SPDX-License-Identifier: GPL-3.0-or-later
// The peers' pseudo-code, in the order our implementations run it: the crusts, the co-cones,
// CGAL's Advancing Front and alpha shapes, the power crust and Boissonnat's sculpting.
#pragma once

#include "pseudo_code_listing.hpp"

namespace sculpt::frontend {

// The crust of Amenta, Bern and Kamvysselis (src/methods/crust/crust_method.hpp).
inline Pseudo_code crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "V <- Voronoi vertices: circumcentres of DT",
      "DT' <- Delaunay(S + V)",
      "crust <- edges of DT' between two samples",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::voronoi, {1}},
                         {Stage::crust_delaunay, {2}},
                         {Stage::surface, {3}}};
  return code;
}

// The nearest-neighbour crust of Dey and Kumar (src/methods/crust/nn_crust.hpp).
inline Pseudo_code nn_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    q <- nearest Delaunay neighbour of s",
      "    r <- nearest at > 90 degrees from q",
      "    keep sq, sr",
  };
  code.lines_of_stage = {
      {Stage::samples, {0}}, {Stage::delaunay, {0}}, {Stage::surface, {4, 2, 3}}};
  return code;
}

// The manifold extraction the crust and the co-cone share (extract_manifold in
// src/methods/extraction/manifold_extraction.hpp), appended; returns its first line. Its last
// line makes the surface.
inline int add_manifold_extraction_lines(Pseudo_code& code) {
  const int first = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "prune t on an edge whose triangles fit in",
                                          "    90 deg (a sharp fold) or",
                                          "    with an edge of its own (only fins if",
                                          "    that leaves a sample bare), repeatedly",
                                          "surface <- outer boundary of T, walked",
                                      });
  return first;
}

// The crust for surfaces (src/methods/crust/surface_crust.hpp).
inline Pseudo_code surface_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  // clang-format off
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",
      "DT' <- Delaunay(S + P)   # P: the poles",
      "T <- triangles of DT' between samples",
      "drop t if its normal leans from p+(s)-s",
      "    > 45 deg at its widest angle, 67.5 else",
  };
  // clang-format on
  const int pruning = add_manifold_extraction_lines(code);
  code.lines_of_stage = common_stage_lines({2});
  code.lines_of_stage.insert({{Stage::crust_delaunay, {3}},
                              {Stage::candidates, {pruning, 4, 5}},
                              {Stage::surface, {int(code.lines.size()) - 1}}});
  return code;
}

// The co-cone of Amenta, Choi, Dey and Leekha (src/methods/cocone/cocone_method.hpp).
inline Pseudo_code cocone_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    v(s) <- p+(s) - s   # pole vector",
      "    cocone(s) <- directions within 22.5 deg",
      "                 of the plane normal to v(s)",
      "U <- undersampled s: Vor(s) not long and",
      "    thin, or normals of neighbours disagree",
      "T <- triangles t of DT between samples whose",
      "    Voronoi edge meets cocone(s), s in t - U",
  };
  const int pruning = add_manifold_extraction_lines(code);
  code.lines_of_stage = common_stage_lines({2, 3});
  code.lines_of_stage.insert(
      {{Stage::candidates, {7, 5}}, {Stage::surface, {int(code.lines.size()) - 1, pruning}}});
  return code;
}

// The tight co-cone of Dey and Goswami (src/methods/cocone/tight_cocone_method.hpp): the
// co-cone's lines, then the peeling.
inline Pseudo_code tight_cocone_pseudo_code() {
  using scene::Stage;
  Pseudo_code code = cocone_pseudo_code();
  code.lines.back() = "S0 <- outer boundary of T, walked";
  const int first = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "good <- samples with one closed fan in S0",
                                          "out <- cells touching the box; peel from out",
                                          "    across f not in S0 into cell d if a good",
                                          "    s of d is on f, or d's are all bad and f",
                                          "    is not d's smallest facet",
                                          "solid <- cells not peeled",
                                          "surface <- facets solid | out",
                                      });
  // The co-cone's surface is the tight co-cone's first guess S0: shown with the candidates.
  Line_list& candidates = code.lines_of_stage[Stage::candidates];
  const Line_list& s0 = code.lines_of_stage[Stage::surface];
  candidates.insert(candidates.end(), s0.begin(), s0.end());
  code.lines_of_stage[Stage::solid] = {first + 5, first, first + 1};
  code.lines_of_stage[Stage::surface] = {first + 6};
  return code;
}

// CGAL's Advancing Front (src/methods/cgal/advancing_front_method.hpp).
inline Pseudo_code advancing_front_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S)   # CGAL's own, no box",   "surface <- the triangle of smallest radius",
      "while the front (border) has an edge e:",    "    t <- DT triangle on e, smallest radius,",
      "         that keeps an oriented 2-manifold", "    add t to the surface; the front moves",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::front, {5, 3, 4}},
                         {Stage::surface, {2, 1, 3, 5}}};
  return code;
}

// CGAL's alpha shapes (src/methods/cgal/alpha_shape_method.hpp).
inline Pseudo_code alpha_shape_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S)",
      "alpha <- the smallest radius such that the",
      "    cells of DT with circumradius < alpha",
      "    make one solid holding every sample",
      "solid <- those cells",
      "surface <- facets between solid and rest",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::alpha, {2, 4}},
                         {Stage::solid, {4, 1}},
                         {Stage::surface, {5}}};
  return code;
}

// The power crust of Amenta, Choi and Kolluri (src/methods/power_crust/power_crust_method.hpp).
inline Pseudo_code power_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  add_confidence_labelling_lines(code);
  const int crust = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "PD <- power diagram of poles, weight r(p)^2",
                                          "crust <- faces of PD between the cells of",
                                          "    an inner and an outer pole",
                                      });
  code.lines_of_stage.insert({Stage::surface, {crust + 1, crust}});
  return code;
}

// Boissonnat's sculpting (src/methods/boissonnat/boissonnat_method.hpp).
inline Pseudo_code boissonnat_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "solid <- cells of DT whose vertices are in S",
      "while a sample is off the boundary:",
      "    c <- removable cell whose circumsphere",
      "         bulges farthest beyond its boundary",
      "    # removable: 1 facet out, apex off the",
      "    # boundary; 2 out, edge off it (3D)",
      "    solid <- solid - c",
      "surface <- facets solid | rest",
  };
  code.lines_of_stage = {{Stage::samples, {0}},    {Stage::delaunay, {0}}, {Stage::hull, {1}},
                         {Stage::carving, {7, 3}}, {Stage::solid, {7, 3}}, {Stage::surface, {8}}};
  return code;
}

}  // namespace sculpt::frontend
