// SPDX-License-Identifier: GPL-3.0-or-later
// The crust of Amenta, Bern and Kamvysselis (1998), for surfaces:
//   P <- the poles of S (stage 2)
//   DT' <- Delaunay(S ∪ P)
//   T <- the triangles of DT' between three samples     (Voronoi filtering)
//   remove from T each triangle whose normal leans too far from the pole vectors of its
//        vertices                                        (normal filtering)
//   prune T at sharp edges; the surface is the outer boundary of what is left
// In 3D, unlike in the plane, some Voronoi vertices lie near the surface (in flat slivers), so
// the crust inserts only the poles, which lie near the medial axis. A triangle between samples
// survives in DT(S ∪ P) when its circumball holds no pole: it cuts no polar ball, so it lies
// near the surface. The few flat triangles that still pass stand across the surface; the normal
// filter takes them out.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/delaunay.hpp"
#include "../../core/stage_clock.hpp"
#include "../cocone/cocone_method.hpp"
#include "../extraction/manifold_extraction.hpp"

namespace sculpt {

// The normal filter's bounds on the angle between a triangle's normal and a vertex's pole
// vector: tight at the triangle's largest angle, where its normal is best determined, and 3/2
// of that at its two other vertices, as the crust paper suggests. The filter must reject the
// triangles across the inside or the outside, whose normals stand near 90 degrees from the pole
// vectors; triangles of a coarsely sampled curved surface lean by tens of degrees. Measured:
// π/8 leaves 722 of knot1's 3,200 samples off the surface and holes in the built-in torus knot
// and three-holes; π/4 closes all three and bunny00.
inline constexpr double crust_normal_angle = M_PI / 4;

// Whether the triangle's normal lies within the bounds of the pole vectors of its vertices.
inline bool normal_agrees_with_poles(const std::vector<Point<3>>& points,
                                     const std::vector<std::array<double, 3>>& pole_vectors,
                                     const Facet<3>& t) {
  using namespace extraction_detail;
  Vector normal = cross(minus(points[t[1]], points[t[0]]), minus(points[t[2]], points[t[0]]));
  const double length = std::sqrt(dot(normal, normal));
  if (length == 0) return false;
  for (double& x : normal) x /= length;
  // The vertex at the largest angle faces the longest edge.
  int widest = 0;
  double longest = -1;
  for (int j = 0; j < 3; ++j) {
    const Vector opposite_edge = minus(points[t[(j + 1) % 3]], points[t[(j + 2) % 3]]);
    const double edge = dot(opposite_edge, opposite_edge);
    if (edge > longest) {
      longest = edge;
      widest = j;
    }
  }
  for (int j = 0; j < 3; ++j) {
    static const double tight = std::cos(crust_normal_angle),
                        loose = std::cos(1.5 * crust_normal_angle);
    // The pole vector may point either way along the normal.
    if (std::abs(dot(normal, pole_vectors[t[j]])) < (j == widest ? tight : loose)) return false;
  }
  return true;
}

template <class Traits>
void run_surface_crust_method(const typename Traits::Triangulation& /*stage_1*/,
                              Reconstruction<3>& result, Stage_clock& clock) {
  using Kernel = typename Traits::Kernel;
  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_3<Vertex_base>;
  using Crust_triangulation = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

  clock.start("crust");
  const int n = static_cast<int>(result.sample_count());
  auto& crust = result.crust;
  // The samples, then the poles: each vertex knows its index in that list. Inserted as CGAL's
  // range insertion would, reporting progress (the stage is a Delaunay triangulation of about
  // three times the samples).
  std::vector<Point<3>> sites(result.sites.begin(), result.sites.begin() + n);
  sites.reserve(n + result.poles.poles.size());
  for (const auto& pole : result.poles.poles) {
    sites.push_back(pole.center);
    crust.voronoi_vertices.push_back(pole.center);
  }
  Crust_triangulation with_poles;
  insert_in_spatial_order<Traits>(with_poles, sites, 0, clock);
  crust.delaunay.cell_count = with_poles.number_of_finite_cells();
  if (result.options.keep_triangulations) {
    for (auto cell : with_poles.finite_cell_handles()) {
      crust.delaunay.cells.push_back({cell->vertex(0)->info(), cell->vertex(1)->info(),
                                      cell->vertex(2)->info(), cell->vertex(3)->info()});
    }
  }

  clock.start("filtering");
  const std::vector<Point<3>> samples(result.sites.begin(), result.sites.begin() + n);
  const auto vectors = pole_vectors(result);
  auto& chosen = result.candidates.chosen;
  for (auto facet = with_poles.finite_facets_begin(); facet != with_poles.finite_facets_end();
       ++facet) {
    const auto& [cell, opposite] = *facet;
    Facet<3> triangle;
    bool all_samples = true;
    for (int j = 0; j < 3; ++j) {
      triangle[j] = cell->vertex(Traits::facet_vertex[opposite][j])->info();
      all_samples = all_samples && triangle[j] < n;
    }
    if (all_samples && normal_agrees_with_poles(samples, vectors, triangle)) {
      chosen.push_back(triangle);
    }
  }
  extract_manifold(samples, result, clock);
}

}  // namespace sculpt
