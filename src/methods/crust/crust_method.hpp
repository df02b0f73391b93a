// SPDX-License-Identifier: GPL-3.0-or-later
// The crust of Amenta, Bern and Kamvysselis (1998), for plane curves:
//   V <- the Voronoi vertices of S           (circumcentres of the cells of stage 1)
//   DT' <- Delaunay(S ∪ V)
//   crust <- the edges of DT' between two samples
// A Voronoi vertex lies near the medial axis, so the circle of an edge that crosses the region
// between two parts of the curve holds one and the edge is broken; an edge between neighbours
// along the curve keeps an empty circle. Exact on closed curves sampled with epsilon < 0.252.
// With the box corners of stage 1 the outermost Voronoi vertices lie far out; they break no
// edge near the samples.
#pragma once

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/delaunay.hpp"
#include "../../core/stage_clock.hpp"
#include "nn_crust.hpp"

namespace sculpt {

template <class Traits>
void run_crust_method(const typename Traits::Triangulation& triangulation,
                      Reconstruction<2>& result, Stage_clock& clock) {
  using Kernel = typename Traits::Kernel;
  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vertex_base>;
  using Crust_triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

  clock.start("voronoi");
  const int n = static_cast<int>(result.sample_count());
  auto& crust = result.crust;
  // The samples, then the Voronoi vertices: each vertex knows its index in that list.
  std::vector<Point<2>> sites(result.sites.begin(), result.sites.begin() + n);
  sites.reserve(n + result.delaunay.cell_count);
  for (auto cell : Traits::finite_cells(triangulation)) {
    crust.voronoi_vertices.push_back(Traits::from_cgal(Traits::circumcenter(triangulation, cell)));
    sites.push_back(crust.voronoi_vertices.back());
  }

  clock.start("crust");
  // Inserted as CGAL's range insertion would (spatially sorted), reporting progress; a Voronoi
  // vertex repeated (four cocircular samples) is one vertex.
  Crust_triangulation with_voronoi;
  insert_in_spatial_order<Traits>(with_voronoi, sites, 0, clock);
  crust.delaunay.cell_count = with_voronoi.number_of_faces();
  if (result.options.keep_triangulations) {
    for (auto face : with_voronoi.finite_face_handles()) {
      crust.delaunay.cells.push_back(
          {face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()});
    }
  }

  clock.start("surface");
  std::vector<std::pair<int, int>> edges;
  for (auto edge = with_voronoi.finite_edges_begin(); edge != with_voronoi.finite_edges_end();
       ++edge) {
    const auto& [face, i] = *edge;
    const int a = face->vertex(face->cw(i))->info(), b = face->vertex(face->ccw(i))->info();
    if (a < n && b < n) edges.push_back({a, b});
  }
  result.surface = chained_edges(neighbour_lists(n, edges));
}

}  // namespace sculpt
