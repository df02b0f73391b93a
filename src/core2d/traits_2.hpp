// SPDX-License-Identifier: GPL-3.0-or-later
// What the sculpting algorithm needs to know about 2D: CGAL's Delaunay_triangulation_2 with an
// index on every vertex (its site) and every face (its place among the finite faces). The
// algorithm calls faces "cells" in every dimension.
#pragma once

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>

#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../core/exact_circumcentre.hpp"
#include "../core/facet_orientation.hpp"

namespace sculpt {

struct Traits_2 {
  static constexpr int dimension = 2;

  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Cgal_point = Kernel::Point_2;
  using Search_traits = CGAL::Search_traits_2<Kernel>;

  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
  using Face_base = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vertex_base, Face_base>;
  using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
  using Cell_handle = Triangulation::Face_handle;
  // Sorts points paired with their site index (the pair's first member is the point).
  using Spatial_sort_traits = CGAL::Spatial_sort_traits_adapter_2<
      Kernel, CGAL::First_of_pair_property_map<std::pair<Cgal_point, int>>>;

  static Cgal_point to_cgal(const Point<2>& p) { return {p[0], p[1]}; }
  static Point<2> from_cgal(const Cgal_point& p) { return {p.x(), p.y()}; }

  // Inserts p into a Delaunay triangulation (this one, or another with vertices of its own),
  // locating it from the faces around `near` (none: from anywhere).
  template <class Any_triangulation = Triangulation>
  static typename Any_triangulation::Vertex_handle insert_near(
      Any_triangulation& t, const Cgal_point& p, typename Any_triangulation::Vertex_handle near) {
    using Face_handle = typename Any_triangulation::Face_handle;
    return t.insert(
        p, near == typename Any_triangulation::Vertex_handle() ? Face_handle() : near->face());
  }

  static auto finite_cells(const Triangulation& t) { return t.finite_face_handles(); }
  static auto all_cells(const Triangulation& t) { return t.all_face_handles(); }
  static auto finite_vertices(const Triangulation& t) { return t.finite_vertex_handles(); }
  static void incident_cells(const Triangulation& t, Triangulation::Vertex_handle v,
                             std::vector<Cell_handle>& cells) {
    const auto first = t.incident_faces(v);
    auto face = first;
    if (face != nullptr) {
      do cells.push_back(face);
      while (++face != first);
    }
  }
  static Cgal_point exact_circumcenter(Cell_handle c) {
    return exact_circumcentre(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point());
  }
  static Cgal_point circumcenter(const Triangulation& t, Cell_handle c) {
    return circumcentre_or_exact<Cgal_point>([&] { return t.dual(c); },
                                             [&] { return exact_circumcenter(c); });
  }
  // Whether p lies in the circumcircle of c, exactly; `perturbed` decides points on the circle
  // as CGAL's insertion does.
  static bool in_circumball(const Triangulation& t, Cell_handle c, const Cgal_point& p,
                            bool perturbed) {
    return t.side_of_oriented_circle(c, p, perturbed) == CGAL::ON_POSITIVE_SIDE;
  }

  // Vertex j of the edge opposite vertex i, with the face on its left: a closed curve comes out
  // counterclockwise around the region it bounds, its normals pointing outward.
  static constexpr const auto& facet_vertex = Facet_orientation<2>::vertex;
};

}  // namespace sculpt
