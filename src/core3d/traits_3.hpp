// SPDX-License-Identifier: GPL-3.0-or-later
// What the sculpting algorithm needs to know about 3D: CGAL's Delaunay_triangulation_3 with an
// index on every vertex (its site) and every cell (its place among the finite cells).
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>

#include <iterator>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../core/exact_circumcentre.hpp"
#include "../core/facet_orientation.hpp"

namespace sculpt {

struct Traits_3 {
  static constexpr int dimension = 3;

  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Cgal_point = Kernel::Point_3;
  using Search_traits = CGAL::Search_traits_3<Kernel>;

  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
  using Cell_base =
      CGAL::Triangulation_cell_base_with_info_3<int, Kernel,
                                                CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
  using Tds = CGAL::Triangulation_data_structure_3<Vertex_base, Cell_base>;
  using Triangulation = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
  using Cell_handle = Triangulation::Cell_handle;
  // Sorts points paired with their site index (the pair's first member is the point).
  using Spatial_sort_traits = CGAL::Spatial_sort_traits_adapter_3<
      Kernel, CGAL::First_of_pair_property_map<std::pair<Cgal_point, int>>>;

  static Cgal_point to_cgal(const Point<3>& p) { return {p[0], p[1], p[2]}; }
  static Point<3> from_cgal(const Cgal_point& p) { return {p.x(), p.y(), p.z()}; }

  // Inserts p into a Delaunay triangulation (this one, or another with vertices of its own),
  // locating it from the cells around `near` (none: from anywhere).
  template <class Any_triangulation = Triangulation>
  static typename Any_triangulation::Vertex_handle insert_near(
      Any_triangulation& t, const Cgal_point& p, typename Any_triangulation::Vertex_handle near) {
    return t.insert(p, near);
  }

  static auto finite_cells(const Triangulation& t) { return t.finite_cell_handles(); }
  static auto all_cells(const Triangulation& t) { return t.all_cell_handles(); }
  static auto finite_vertices(const Triangulation& t) { return t.finite_vertex_handles(); }
  static void incident_cells(const Triangulation& t, Triangulation::Vertex_handle v,
                             std::vector<Cell_handle>& cells) {
    t.incident_cells(v, std::back_inserter(cells));
  }
  static Cgal_point exact_circumcenter(Cell_handle c) {
    return exact_circumcentre(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                              c->vertex(3)->point());
  }
  static Cgal_point circumcenter(const Triangulation& t, Cell_handle c) {
    return circumcentre_or_exact<Cgal_point>([&] { return t.dual(c); },
                                             [&] { return exact_circumcenter(c); });
  }
  // Whether p lies in the circumball of c, exactly; `perturbed` decides points on its sphere
  // as CGAL's insertion does.
  static bool in_circumball(const Triangulation& t, Cell_handle c, const Cgal_point& p,
                            bool perturbed) {
    return t.side_of_sphere(c, p, perturbed) == CGAL::ON_BOUNDED_SIDE;
  }

  // Vertex j of the facet opposite vertex i, facing away from vertex i.
  static constexpr const auto& facet_vertex = Facet_orientation<3>::vertex;
};

}  // namespace sculpt
