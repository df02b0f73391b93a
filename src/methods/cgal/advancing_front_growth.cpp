// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's Advancing Front, run so that the order of its triangles is kept: CGAL tells the cell of
// each facet it selects (Advancing_front_surface_reconstruction::select_facet), but its cell base
// forgets unless compiled with AFSR_FACET_NUMBER. A cell base of our own stamps each selection in
// order; everything else is CGAL's class with its default parameters, the same call
// advancing_front_surface_reconstruction() makes (src/yardsticks), so the surface is the same on
// samples in general position. Where candidates tie (cospherical samples, as CAD meshes have),
// CGAL's choice follows the cells' places in memory: two runs of its own call on CGAL's dino,
// helmet or cube-meshed, with other allocations between them, give different triangles, and so
// does this run with its larger cells.
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "advancing_front_method.hpp"

namespace sculpt {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The order of selection, over all cells of one run (advancing_front_in_order resets it).
thread_local int selections = 0;

// CGAL's cell base for the Advancing Front, with each facet's place in the order kept (hiding
// its no-ops). CGAL's own numbers will not do after its post-processing: it counts down as it
// takes triangles back, so later triangles reuse numbers. So each selection is stamped in order
// instead, above every number CGAL counts to; a stamp CGAL hands back (it moves a selected
// facet to its mirror when a vertex is inserted, number and all) is kept as it is.
template <class Base = CGAL::Advancing_front_surface_reconstruction_cell_base_3<Kernel>>
class Numbered_facets_cell : public Base {
 public:
  template <class Tds2>
  struct Rebind_TDS {
    using Other = Numbered_facets_cell<typename Base::template Rebind_TDS<Tds2>::Other>;
  };
  using Base::Base;

  static constexpr int first_stamp = 1 << 30;  // beyond any count of facets CGAL selects

  void set_facet_number(int i, int n) {
    numbers_[i] = n >= first_stamp ? n : first_stamp + selections++;
  }
  int facet_number(int i) const { return numbers_[i]; }

 private:
  std::array<int, 4> numbers_{-1, -1, -1, -1};
};

using Vertex_base = CGAL::Advancing_front_surface_reconstruction_vertex_base_3<Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<Vertex_base, Numbered_facets_cell<>>;
using Triangulation = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Front = CGAL::Advancing_front_surface_reconstruction<Triangulation>;

}  // namespace

std::vector<Facet<3>> advancing_front_in_order(const std::vector<Point<3>>& points) {
  std::vector<std::pair<Kernel::Point_3, std::size_t>> numbered;
  numbered.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    numbered.push_back({{points[i][0], points[i][1], points[i][2]}, i});
  Triangulation triangulation(numbered.begin(), numbered.end());
  if (triangulation.dimension() < 3) return {};
  selections = 0;
  Front front(triangulation);
  front.run();  // radius_ratio_bound 5, beta 0.52: CGAL's defaults

  // Each surface triangle with the number of its selection (on whichever side CGAL selected it).
  std::vector<std::pair<int, Facet<3>>> numbered_triangles;
  const auto& surface = front.triangulation_data_structure_2();
  for (auto face = surface.faces_begin(); face != surface.faces_end(); ++face) {
    if (!face->is_on_surface()) continue;
    auto [cell, index] = face->facet();
    if (!cell->is_selected_facet(index)) {
      const auto mirror = triangulation.mirror_facet({cell, index});
      cell = mirror.first;
      index = mirror.second;
    }
    Facet<3> triangle;
    for (int j = 0; j < 3; ++j) triangle[j] = static_cast<int>(face->vertex(j)->vertex_3()->id());
    numbered_triangles.push_back({cell->facet_number(index), triangle});
  }
  // A triangle never stamped (none is expected) goes last rather than first.
  const auto stamp = [](int number) {
    return number < 0 ? std::numeric_limits<int>::max() : number;
  };
  std::stable_sort(numbered_triangles.begin(), numbered_triangles.end(),
                   [&](const auto& a, const auto& b) { return stamp(a.first) < stamp(b.first); });
  std::vector<Facet<3>> triangles;
  triangles.reserve(numbered_triangles.size());
  for (const auto& [number, triangle] : numbered_triangles) triangles.push_back(triangle);
  return triangles;
}

}  // namespace sculpt
