// SPDX-License-Identifier: GPL-3.0-or-later
// The co-cone of Amenta, Choi, Dey and Leekha (2000), with the undersampling detection of Dey
// and Giesen (2001) that Kuo & Yau compare against (their Fig. 15b, the "modified co-cone"):
//   for each sample p: v_p <- p+ - p, the direction to its positive pole (stage 2)
//     cocone(p) <- the directions from p within θ = π/8 of the plane normal to v_p
//   U <- the undersampled samples (undersampling.hpp)
//   T <- the Delaunay triangles of S whose dual Voronoi edge meets the co-cone of each of
//        their vertices not in U (and that have one)
//   prune T at sharp edges; the surface is the outer boundary of what is left
// Near a well-sampled surface the pole vector is close to the normal, so the co-cone is a thick
// slab about the tangent plane and the Voronoi edges dual to surface triangles cross it; a
// triangle across the inside or the outside has a Voronoi edge along the normal, inside the
// cone, and is left out (ACDL 2000, sections 3 and 4).
//
// The Delaunay triangulation and the poles are stage 1 and 2, shared with every method: the
// box corners of stage 1 make every triangle between samples interior, so its Voronoi edge
// joins two finite circumcentres.
#pragma once

#include <cmath>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/stage_clock.hpp"
#include "../extraction/manifold_extraction.hpp"
#include "undersampling.hpp"

namespace sculpt {

// The angle between the co-cone and the plane normal to the pole vector (ACDL 2000: π/8).
inline constexpr double cocone_angle = M_PI / 8;

// Whether the segment from `from` to `to` meets the co-cone of p, given the unit pole vector:
// the co-cone is the set of directions whose cosine with v_p is at most sin θ in absolute value;
// outside it lie two convex cones, one along +v_p and one along -v_p. A segment misses the
// co-cone exactly when both its ends lie in the same one.
inline bool segment_meets_cocone(const Point<3>& p, const std::array<double, 3>& pole_vector,
                                 const Point<3>& from, const Point<3>& to) {
  using namespace extraction_detail;
  static const double bound = std::sin(cocone_angle);
  const auto side = [&](const Point<3>& q) {
    const Vector d = minus(q, p);
    const double length = std::sqrt(dot(d, d));
    if (length == 0) return 0;  // the segment passes through p: it meets the co-cone
    const double cosine = dot(d, pole_vector) / length;
    return cosine > bound ? 1 : cosine < -bound ? -1 : 0;
  };
  const int a = side(from), b = side(to);
  return a == 0 || b == 0 || a != b;
}

// Unit vectors from each sample to its positive pole.
inline std::vector<std::array<double, 3>> pole_vectors(const Reconstruction<3>& result) {
  using namespace extraction_detail;
  const int n = static_cast<int>(result.sample_count());
  std::vector<std::array<double, 3>> vectors(n, {0, 0, 0});
  for (int s = 0; s < n; ++s) {
    const int pole = result.poles.positive_pole[s];
    if (pole < 0) continue;
    Vector v = minus(result.poles.poles[pole].center, result.sites[s]);
    const double length = std::sqrt(dot(v, v));
    if (length == 0) continue;
    for (double& x : v) x /= length;
    vectors[s] = v;
  }
  return vectors;
}

template <class Traits>
void run_cocone_method(const typename Traits::Triangulation& triangulation,
                       Reconstruction<3>& result, Stage_clock& clock) {
  const int n = static_cast<int>(result.sample_count());
  const auto vectors = pole_vectors(result);

  clock.start("cocone");
  std::vector<Point<3>> circumcentres(result.delaunay.cell_count);
  for (auto cell : Traits::finite_cells(triangulation)) {
    circumcentres[cell->info()] = Traits::from_cgal(Traits::circumcenter(triangulation, cell));
  }
  // Every triangle between samples: its Voronoi edge widens its vertices' cells and is kept, with
  // the co-cones it meets, if it meets one.
  std::vector<Cocone_triangle> triangles;
  std::vector<double> width(n, 0.0);
  const std::size_t expected_facets = 2 * result.delaunay.cell_count;
  std::size_t visited = 0;
  for (auto facet = triangulation.finite_facets_begin(); facet != triangulation.finite_facets_end();
       ++facet) {
    clock.report_every(++visited, expected_facets, 65536);
    const auto& [cell, opposite] = *facet;
    const auto other = cell->neighbor(opposite);
    if (triangulation.is_infinite(cell) || triangulation.is_infinite(other)) continue;
    Cocone_triangle t;
    bool all_samples = true;
    for (int j = 0; j < 3; ++j) {
      t.samples[j] = cell->vertex(Traits::facet_vertex[opposite][j])->info();
      all_samples = all_samples && t.samples[j] < n;
    }
    if (!all_samples) continue;
    const Point<3>& from = circumcentres[cell->info()];
    const Point<3>& to = circumcentres[other->info()];
    widen_by_voronoi_edge(result, vectors, t.samples, from, to, width);
    bool meets_one = false;
    for (int j = 0; j < 3; ++j) {
      const int v = t.samples[j];
      t.meets_cocone[j] = segment_meets_cocone(result.sites[v], vectors[v], from, to);
      meets_one = meets_one || t.meets_cocone[j];
    }
    if (meets_one) triangles.push_back(t);
  }
  circumcentres = {};

  clock.start("undersampling");
  const std::vector<bool> undersampled = undersampled_samples(result, vectors, width, triangles);
  for (int s = 0; s < n; ++s) {
    if (undersampled[s]) result.candidates.undersampled.push_back(s);
  }
  result.stats.undersampled_samples = result.candidates.undersampled.size();

  // A triangle is chosen when its Voronoi edge meets the co-cone of each of its well-sampled
  // vertices, and it has one; an undersampled vertex imposes nothing (Dey & Giesen 2001).
  auto& chosen = result.candidates.chosen;
  for (const auto& t : triangles) {
    bool well_sampled_vertex = false, meets_theirs = true;
    for (int j = 0; j < 3; ++j) {
      if (undersampled[t.samples[j]]) continue;
      well_sampled_vertex = true;
      meets_theirs = meets_theirs && t.meets_cocone[j];
    }
    if (well_sampled_vertex && meets_theirs) chosen.push_back(t.samples);
  }
  triangles = {};
  extract_manifold({result.sites.begin(), result.sites.begin() + n}, result, clock);
}

}  // namespace sculpt
