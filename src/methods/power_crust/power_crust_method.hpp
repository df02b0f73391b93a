// SPDX-License-Identifier: GPL-3.0-or-later
// The power crust of Amenta, Choi and Kolluri (2001), for closed curves and surfaces:
//   for each sample s: p+(s), p-(s) <- its poles, each with its polar ball   (stage 2, shared)
//   label the poles inner or outer, most confident first                      (ACK 2001, sec. 5)
//   PD <- the power diagram of the poles, pole p weighted by r(p)^2     (stage "power diagram")
//   crust <- the faces of PD between the cells of inner and outer poles   (stage "power-crust")
// The union of the inner polar balls approximates the solid and the outer ones its complement;
// where an inner and an outer power cell meet is the surface. Its vertices are the power
// diagram's (the weighted circumcentres of the regular triangulation's cells), not the samples:
// the power crust does not interpolate, and has several times more vertices than samples.
//
// The labelling is the confidence labelling the robust method uses (it is modelled on the power
// crust's, section 5 of ACK: a priority queue over the evidence that two balls meeting deeply at
// a sample lie on one side and that the two poles of a sample lie on opposite sides). The power
// diagram is the dual of CGAL's regular triangulation of the weighted poles: an edge between an
// inner and an outer pole is dual to one face of the crust, a polygon (3D) or a segment (2D)
// through the weighted circumcentres of the cells around that edge.
#pragma once

#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_face_base_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../core/exact_circumcentre.hpp"
#include "../../core/label_statistics.hpp"
#include "../../core/seeds.hpp"
#include "../../core/stage_clock.hpp"
#include "../robust/confidence_labelling.hpp"

namespace sculpt {

namespace power_crust_detail {

// The crust's vertices: one per cell of the regular triangulation, numbered as first met. Cells
// whose weighted circumcentres coincide, or lie a rounding error apart (poles nearly on one
// sphere), keep a vertex each: joining them would join power diagram vertices that are not
// adjacent and tear the crust (merging those within 2^-30 gave the built-in bumpy sphere 310
// non-manifold edges, merging exact copies gave CGAL's knot1 two), whereas the crust of the
// perturbed diagram is always a 2-manifold. It keeps their faces of nearly zero area.
template <int D>
class Vertex_pool {
 public:
  explicit Vertex_pool(std::vector<Point<D>>& vertices) : vertices_(vertices) {}
  int index_of(const Point<D>& p) {
    vertices_.push_back(p);
    return static_cast<int>(vertices_.size()) - 1;
  }

 private:
  std::vector<Point<D>>& vertices_;
};

// The weighted circumcentre (the point of equal power to the cell's weighted points: a vertex of
// the power diagram) of a cell of a regular triangulation. CGAL's floating-point construction,
// unless it is not finite or misses equal power by more than a millionth of the cell's size
// squared (a cell nearly flat: poles often lie nearly on one sphere); then exactly, rounded.
template <int D, class Weighted>
Point<D> weighted_circumcentre(const std::array<Weighted, D + 1>& cell, const Point<D>& inexact) {
  const auto power = [&](const Point<D>& x, const Weighted& w) {
    double squared = 0;
    for (int k = 0; k < D; ++k) squared += (x[k] - w.point()[k]) * (x[k] - w.point()[k]);
    return squared - w.weight();
  };
  double size = 0;
  for (const auto& w : cell) {
    for (int k = 0; k < D; ++k) size = std::max(size, std::abs(w.point()[k] - cell[0].point()[k]));
  }
  bool accurate = true;
  for (int k = 0; k < D; ++k) accurate = accurate && std::isfinite(inexact[k]);
  for (int j = 1; j <= D && accurate; ++j) {
    accurate = std::abs(power(inexact, cell[j]) - power(inexact, cell[0])) <= 1e-6 * size * size;
  }
  if (accurate) return inexact;
  using Exact = Exact_rational_kernel;
  using Exact_weighted =
      typename std::conditional<D == 2, Exact::Weighted_point_2, Exact::Weighted_point_3>::type;
  std::array<Exact_weighted, D + 1> exact;
  for (int j = 0; j <= D; ++j) {
    const auto& p = cell[j].point();
    if constexpr (D == 2) {
      exact[j] = Exact_weighted(Exact::Point_2(p.x(), p.y()), cell[j].weight());
    } else {
      exact[j] = Exact_weighted(Exact::Point_3(p.x(), p.y(), p.z()), cell[j].weight());
    }
  }
  Point<D> rounded;
  if constexpr (D == 2) {
    const auto c = Exact().construct_weighted_circumcenter_2_object()(exact[0], exact[1], exact[2]);
    rounded = {CGAL::to_double(c.x()), CGAL::to_double(c.y())};
  } else {
    const auto c =
        Exact().construct_weighted_circumcenter_3_object()(exact[0], exact[1], exact[2], exact[3]);
    rounded = {CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z())};
  }
  return rounded;
}

// CGAL's regular triangulations whose vertices know their poles (and cells, faces in 2D, a
// number of their own).
template <class Kernel>
using Regular_3 = CGAL::Regular_triangulation_3<
    Kernel, CGAL::Triangulation_data_structure_3<
                CGAL::Triangulation_vertex_base_with_info_3<
                    int, Kernel, CGAL::Regular_triangulation_vertex_base_3<Kernel>>,
                CGAL::Triangulation_cell_base_with_info_3<
                    int, Kernel, CGAL::Regular_triangulation_cell_base_3<Kernel>>>>;
template <class Kernel>
using Regular_2 = CGAL::Regular_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<
                CGAL::Triangulation_vertex_base_with_info_2<
                    int, Kernel, CGAL::Regular_triangulation_vertex_base_2<Kernel>>,
                CGAL::Triangulation_face_base_with_info_2<
                    int, Kernel, CGAL::Regular_triangulation_face_base_2<Kernel>>>>;
template <int D, class Kernel>
using Regular = std::conditional_t<D == 3, Regular_3<Kernel>, Regular_2<Kernel>>;

// The poles as weighted points (centre, squared radius), each with its index.
template <class Kernel, int D>
auto weighted_poles(const Reconstruction<D>& result) {
  using Weighted = typename Regular<D, Kernel>::Weighted_point;
  const auto& poles = result.poles.poles;
  std::vector<std::pair<Weighted, int>> weighted;
  weighted.reserve(poles.size());
  for (std::size_t p = 0; p < poles.size(); ++p) {
    const Point<D>& c = poles[p].center;
    const double weight = poles[p].radius * poles[p].radius;
    if constexpr (D == 3) {
      weighted.push_back({Weighted(typename Kernel::Point_3(c[0], c[1], c[2]), weight), int(p)});
    } else {
      weighted.push_back({Weighted(typename Kernel::Point_2(c[0], c[1]), weight), int(p)});
    }
  }
  return weighted;
}

// The power diagram's dual: the regular triangulation of the poles, pole p weighted by r(p)^2,
// its vertices knowing their poles. The poles are inserted one at a time, as CGAL's insertion of
// a range with infos does it (sorted in space the same way, each located from the last one
// inserted), so that the stage can report progress: it is most of the method's time (bunny00:
// 0.93 s of 1.25; the poles through one sample all have power 0 at it, so CGAL's predicates
// often fall back on exact arithmetic). The triangulation is the same and numbered the same as
// the range insertion's. (No pole is hidden but by such a tie: a pole's samples lie in its power
// cell, at power 0 from it and not inside any other empty ball. CGAL's handling of one is
// followed all the same.)
template <class Kernel, int D>
void build_power_diagram(Regular<D, Kernel>& regular, const Reconstruction<D>& result,
                         const Stage_clock& clock) {
  using Triangulation = Regular<D, Kernel>;
  using Bare = std::conditional_t<D == 3, typename Kernel::Point_3, typename Kernel::Point_2>;
  const auto weighted = weighted_poles<Kernel>(result);
  std::vector<Bare> bare;
  bare.reserve(weighted.size());
  for (const auto& [point, pole] : weighted) bare.push_back(point.point());
  std::vector<std::size_t> order(weighted.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Bare_of_index = typename CGAL::Pointer_property_map<Bare>::type;
  using Sort_traits =
      std::conditional_t<D == 3, CGAL::Spatial_sort_traits_adapter_3<Kernel, Bare_of_index>,
                         CGAL::Spatial_sort_traits_adapter_2<Kernel, Bare_of_index>>;
  CGAL::spatial_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(bare)));
  if constexpr (D == 3) {
    typename Triangulation::Cell_handle hint;
    for (std::size_t k = 0; k < order.size(); ++k) {
      clock.report_every(k, order.size(), 4096);
      const auto& [point, pole] = weighted[order[k]];
      typename Triangulation::Locate_type type;
      int li, lj;
      const auto cell = regular.locate(point, type, li, lj, hint);
      const auto vertex = regular.insert(point, type, cell, li, lj);
      if (vertex == typename Triangulation::Vertex_handle()) {
        hint = cell;  // hidden
      } else {
        vertex->info() = pole;
        hint = vertex->cell();
      }
    }
  } else {
    typename Triangulation::Face_handle hint;
    for (std::size_t k = 0; k < order.size(); ++k) {
      clock.report_every(k, order.size(), 4096);
      const auto& [point, pole] = weighted[order[k]];
      const auto vertex = regular.insert(point, hint);
      // (CGAL returns a hidden pole as a hidden vertex in 2D; none only while it is empty.)
      if (vertex != typename Triangulation::Vertex_handle()) {
        vertex->info() = pole;
        hint = vertex->face();
      }
    }
  }
}

// Whether the edge between two poles separates an inner cell from an outer one; `inner_first`
// says which end is inner.
inline bool separates(const std::vector<Label>& labels, int a, int b, bool& inner_first) {
  const Label la = labels[a], lb = labels[b];
  if (la == Label::unlabelled || lb == Label::unlabelled || la == lb) return false;
  inner_first = la == Label::inner;
  return true;
}

// The power faces between inner and outer cells, in 3D: for every edge of the regular
// triangulation from an inner to an outer pole, the polygon of the weighted circumcentres of
// the cells around it, fanned into triangles facing from the inner pole to the outer one.
template <class Kernel>
void power_faces_3(Regular_3<Kernel>& regular, const Reconstruction<3>& result,
                   std::vector<Point<3>>& vertices, std::vector<Facet<3>>& faces,
                   std::size_t& unbounded_faces, const Stage_clock& clock) {
  using Regular = Regular_3<Kernel>;
  using Weighted = typename Kernel::Weighted_point_3;

  const auto& labels = result.propagation.labels;
  // Cells numbered in the container's order, which does not depend on addresses; each gets its
  // crust vertex when first used.
  int cells = 0;
  for (auto cell : regular.all_cell_handles()) cell->info() = cells++;
  std::vector<int> vertex_of_cell(cells, -1);

  Vertex_pool<3> pool(vertices);
  const auto vertex_of = [&](typename Regular::Cell_handle cell) {
    int& vertex = vertex_of_cell[cell->info()];
    if (vertex < 0) {
      const auto centre = regular.dual(cell);
      const std::array<Weighted, 4> points = {cell->vertex(0)->point(), cell->vertex(1)->point(),
                                              cell->vertex(2)->point(), cell->vertex(3)->point()};
      vertex =
          pool.index_of(weighted_circumcentre<3>(points, {centre.x(), centre.y(), centre.z()}));
    }
    return vertex;
  };
  // The faces in the order of their poles; each is drawn the same from any cell around its edge.
  // A separating edge is read off a cell around it that is numbered below its two neighbours in
  // the ring of cells about the edge (the lowest of the ring is one: each edge is found at least
  // once, rarely more), then the edges are sorted and made unique. CGAL's edge iterator, which
  // reports each edge once, walks around every edge of every cell to decide whether this cell
  // reports it (bunny00: 0.2 s of 1.7); one entry per cell around each edge doubled the
  // method's peak memory.
  std::vector<std::pair<std::pair<int, int>, typename Regular::Edge>> separating;
  for (auto cell : regular.all_cell_handles()) {
    for (int i = 0; i < 3; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        const auto u = cell->vertex(i), v = cell->vertex(j);
        if (regular.is_infinite(u) || regular.is_infinite(v)) continue;
        bool inner_first = false;
        if (!separates(labels, u->info(), v->info(), inner_first)) continue;
        // The ring's neighbours of this cell: across the facets opposite its two other vertices.
        bool lowest = true;
        for (int k = 0; k < 4 && lowest; ++k) {
          if (k != i && k != j) lowest = cell->info() < cell->neighbor(k)->info();
        }
        if (lowest) {
          separating.push_back(
              {std::minmax(u->info(), v->info()), typename Regular::Edge(cell, i, j)});
        }
      }
    }
  }
  std::sort(separating.begin(), separating.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  separating.erase(std::unique(separating.begin(), separating.end(),
                               [](const auto& x, const auto& y) { return x.first == y.first; }),
                   separating.end());
  std::vector<typename Regular::Cell_handle> around;
  std::vector<int> ring;
  for (std::size_t k = 0; k < separating.size(); ++k) {
    clock.report_every(k, separating.size(), 4096);
    const auto& edge = separating[k].second;
    const auto u = edge.first->vertex(edge.second), v = edge.first->vertex(edge.third);
    bool inner_first = false;
    separates(labels, u->info(), v->info(), inner_first);
    around.clear();
    bool bounded = true;
    auto cell = regular.incident_cells(edge), first = cell;
    const auto second = std::next(first);
    do {
      if (regular.is_infinite(cell)) {
        bounded = false;
        break;
      }
      around.push_back(cell);
    } while (++cell != first);
    if (!bounded) {
      ++unbounded_faces;
      continue;
    }
    // Start the polygon at its cell first in the container and go on toward the lower of its
    // two neighbours, whatever cell and direction the circulator began with.
    std::rotate(around.begin(),
                std::min_element(around.begin(), around.end(),
                                 [](auto x, auto y) { return x->info() < y->info(); }),
                around.end());
    const bool backward = around.size() > 2 && around[1]->info() > around.back()->info();
    if (backward) std::reverse(around.begin() + 1, around.end());
    ring.clear();
    for (auto c : around) ring.push_back(vertex_of(c));
    if (ring.size() < 3) continue;  // the face has no area
    // The polygon turns about the edge u -> v as its cells do, and the cells' turn is decided
    // exactly from the poles (the polygon's own vertices may be a rounding error apart): from
    // the first cell's vertex y that the second cell lacks, to x that it shares.
    typename Regular::Vertex_handle x, y;
    for (int j = 0; j < 4; ++j) {
      const auto w = first->vertex(j);
      if (w == u || w == v) continue;
      (second->has_vertex(w) ? x : y) = w;
    }
    const auto bare = [](typename Regular::Vertex_handle w) { return w->point().point(); };
    const bool turns_positively =
        CGAL::orientation(bare(u), bare(v), bare(y), bare(x)) == CGAL::POSITIVE;
    // Counterclockwise seen from v, the fan faces along u -> v: toward the outer pole if u is
    // the inner one.
    const bool reversed = (turns_positively != inner_first) != backward;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      if (reversed) {
        faces.push_back({ring[0], ring[k + 1], ring[k]});
      } else {
        faces.push_back({ring[0], ring[k], ring[k + 1]});
      }
    }
  }
}

// The same in 2D: every edge of the regular triangulation between an inner and an outer pole is
// dual to a segment between the weighted circumcentres of its two faces, directed with the
// inner pole on its left (a closed curve then runs counterclockwise around what it encloses).
template <class Kernel>
void power_faces_2(Regular_2<Kernel>& regular, const Reconstruction<2>& result,
                   std::vector<Point<2>>& vertices, std::vector<Facet<2>>& faces,
                   std::size_t& unbounded_faces) {
  using Regular = Regular_2<Kernel>;
  using Weighted = typename Kernel::Weighted_point_2;

  const auto& labels = result.propagation.labels;
  int faces_counted = 0;
  for (auto face : regular.all_face_handles()) face->info() = faces_counted++;
  std::vector<int> vertex_of_face(faces_counted, -1);

  Vertex_pool<2> pool(vertices);
  const auto vertex_of = [&](typename Regular::Face_handle face) {
    int& vertex = vertex_of_face[face->info()];
    if (vertex < 0) {
      const auto centre = regular.weighted_circumcenter(face);
      const std::array<Weighted, 3> points = {face->vertex(0)->point(), face->vertex(1)->point(),
                                              face->vertex(2)->point()};
      vertex = pool.index_of(weighted_circumcentre<2>(points, {centre.x(), centre.y()}));
    }
    return vertex;
  };
  // In the order of their poles (see power_faces_3).
  std::vector<std::pair<std::pair<int, int>, typename Regular::Edge>> separating;
  for (auto edge = regular.finite_edges_begin(); edge != regular.finite_edges_end(); ++edge) {
    const auto [face, i] = *edge;
    const int a = face->vertex(face->cw(i))->info(), b = face->vertex(face->ccw(i))->info();
    bool inner_first = false;
    if (separates(labels, a, b, inner_first)) separating.push_back({std::minmax(a, b), *edge});
  }
  std::sort(separating.begin(), separating.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [poles_of_edge, reported] : separating) {
    // Seen from its face first in the container, whichever one CGAL reported it from.
    const auto edge = reported.first->info() < reported.first->neighbor(reported.second)->info()
                          ? reported
                          : regular.mirror_edge(reported);
    const auto [face, i] = edge;
    const auto u = face->vertex(face->cw(i)), v = face->vertex(face->ccw(i));
    bool inner_first = false;
    separates(labels, u->info(), v->info(), inner_first);
    const auto other = face->neighbor(i);
    if (regular.is_infinite(face) || regular.is_infinite(other)) {
      ++unbounded_faces;
      continue;
    }
    const int a = vertex_of(face), b = vertex_of(other);
    if (a == b) continue;
    // `face` lies right of u -> v (its vertices i, ccw(i) = v, cw(i) = u run counterclockwise),
    // and the dual edge runs from `other`'s weighted circumcentre to `face`'s across u -> v,
    // so v is on its left. Keep the inner pole on the left.
    if (inner_first) {
      faces.push_back({a, b});
    } else {
      faces.push_back({b, a});
    }
  }
}

}  // namespace power_crust_detail

template <class Traits>
void run_power_crust_method(Reconstruction<Traits::dimension>& result, Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  clock.start("seeds");
  select_seeds(result);
  clock.start("labelling");
  label_poles_by_confidence(result, clock);
  count_labels(result);

  clock.start("power diagram");
  using Kernel = typename Traits::Kernel;
  power_crust_detail::Regular<D, Kernel> regular;
  power_crust_detail::build_power_diagram<Kernel>(regular, result, clock);
  clock.start("power-crust");
  std::size_t unbounded = 0;
  if constexpr (D == 3) {
    power_crust_detail::power_faces_3<Kernel>(regular, result, result.surface_vertices,
                                              result.surface, unbounded, clock);
  } else {
    power_crust_detail::power_faces_2<Kernel>(regular, result, result.surface_vertices,
                                              result.surface, unbounded);
  }
  result.stats.unbounded_power_faces = unbounded;
}

}  // namespace sculpt
