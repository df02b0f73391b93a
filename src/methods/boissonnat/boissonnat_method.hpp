// SPDX-License-Identifier: GPL-3.0-or-later
// Boissonnat's sculpting (1984, "Geometric structures for three-dimensional shape
// representation", sec. 4), the greedy method Kuo & Yau start from (their sec. 1.3):
//   solid <- the Delaunay cells of S (its convex hull)
//   while some sample is not on the boundary of the solid:
//       among the cells with a facet on the boundary whose removal keeps the boundary a
//       polyhedron through the same samples, remove the one whose circumsphere bulges farthest
//       out of its boundary facets
//   surface <- the boundary of what is left
// A cell may go when it touches the outside through k facets and
//   k = 1  its opposite vertex is not on the boundary yet (it comes onto it), or
//   k = 2  (3D) its opposite edge is not on the boundary (the boundary gains that edge);
// with k = 3 (k = 2 in 2D) a sample would leave the boundary, and that is never allowed. The
// bulge of a cell over a boundary facet f is the height of its circumsphere's cap beyond f:
// R + sqrt(R^2 - r_f^2) when the circumcentre lies beyond f, R - sqrt(R^2 - r_f^2) when not (R
// the cell's circumradius, r_f the facet's): a large empty sphere reaching far out of the solid
// marks a cell spanning a concavity. One global greedy order, no notion of inside or outside:
// the lesson is where it goes wrong (it stops as soon as every sample is on the boundary, so a
// concavity whose samples are reached early keeps its cells, and it may stop before that, no
// cell being removable).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/cells_around_edge.hpp"
#include "../../core/solid_and_skin.hpp"
#include "../../core/stage_clock.hpp"

namespace sculpt {

template <class Traits>
class Boissonnat_sculpting {
  static constexpr int D = Traits::dimension;
  using Triangulation = typename Traits::Triangulation;
  using Cell_handle = typename Traits::Cell_handle;

 public:
  Boissonnat_sculpting(const Triangulation& triangulation, Reconstruction<D>& result)
      : triangulation_(triangulation),
        result_(result),
        n_(static_cast<int>(result.sample_count())),
        outside_(result.delaunay.cell_count, 0),
        boundary_facets_at_(n_, 0) {}

  void run(const Stage_clock& clock) {
    // The hull: every all-sample cell; the cells with a box corner are the outside.
    for (auto cell : Traits::finite_cells(triangulation_)) {
      for (int i = 0; i <= D; ++i) outside_[cell->info()] |= cell->vertex(i)->info() >= n_;
    }
    int off_boundary = n_;
    for (auto cell : Traits::finite_cells(triangulation_)) {
      if (is_outside(cell)) continue;
      for (int i = 0; i <= D; ++i) {
        if (!is_outside(cell->neighbor(i))) continue;
        for (int j = 0; j < D; ++j) {
          off_boundary -= boundary_facets_at_[facet_vertex(cell, i, j)]++ == 0;
        }
        push(cell);
      }
    }
    std::size_t removed = 0;
    while (off_boundary > 0 && !queue_.empty()) {
      const auto [bulge, index, cell] = queue_.top();
      queue_.pop();
      if (is_outside(cell)) continue;
      const double now = bulge_of(cell);
      if (now != bulge) {  // its boundary facets changed since it was queued
        queue_.push({now, index, cell});
        continue;
      }
      if (!can_remove(cell)) continue;  // queued again when a neighbour goes
      // The cell's facets toward the solid become boundary, those toward the outside stop being.
      for (int i = 0; i <= D; ++i) {
        const int change = is_outside(cell->neighbor(i)) ? -1 : 1;
        for (int j = 0; j < D; ++j) {
          int& count = boundary_facets_at_[facet_vertex(cell, i, j)];
          off_boundary += (count == 0) - (count + change == 0);
          count += change;
        }
      }
      outside_[cell->info()] = 1;
      result_.carving.events.push_back({cell->info(), Carve_reason::largest_bulge});
      for (int i = 0; i <= D; ++i) {
        if (!is_outside(cell->neighbor(i))) push(cell->neighbor(i));
      }
      if (++removed % 65536 == 0) clock.report(double(removed) / double(outside_.size()));
    }
  }

  bool is_outside(Cell_handle cell) const {
    return triangulation_.is_infinite(cell) || outside_[cell->info()];
  }

 private:
  struct Entry {
    double bulge;
    int index;
    Cell_handle cell;
    // Largest bulge first; ties to the lowest cell index (an order independent of the queue).
    bool operator<(const Entry& other) const {
      return bulge < other.bulge || (bulge == other.bulge && index > other.index);
    }
  };

  int facet_vertex(Cell_handle cell, int facet, int j) const {
    return cell->vertex(Traits::facet_vertex[facet][j])->info();
  }

  void push(Cell_handle cell) { queue_.push({bulge_of(cell), cell->info(), cell}); }

  // The largest height of the circumsphere's cap beyond one of the cell's boundary facets.
  double bulge_of(Cell_handle cell) const {
    const Point<D> centre = Traits::from_cgal(Traits::circumcenter(triangulation_, cell));
    const auto squared = [&](const Point<D>& a, const Point<D>& b) {
      double sum = 0;
      for (int k = 0; k < D; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
      return sum;
    };
    const auto& sites = result_.sites;
    const double r2 = squared(centre, sites[cell->vertex(0)->info()]);
    double largest = -INFINITY;
    for (int i = 0; i <= D; ++i) {
      if (!is_outside(cell->neighbor(i))) continue;
      // The distance from the centre to the facet's hyperplane, signed positive beyond it (away
      // from the opposite vertex): then the facet's circumradius^2 is R^2 - distance^2.
      const Point<D>& apex = sites[cell->vertex(i)->info()];
      const Point<D>& a = sites[facet_vertex(cell, i, 0)];
      std::array<double, D> normal{};
      if constexpr (D == 2) {
        const Point<2>& b = sites[facet_vertex(cell, i, 1)];
        normal = {b[1] - a[1], a[0] - b[0]};
      } else {
        const Point<3>& b = sites[facet_vertex(cell, i, 1)];
        const Point<3>& c = sites[facet_vertex(cell, i, 2)];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      }
      double length2 = 0, to_centre = 0, to_apex = 0;
      for (int k = 0; k < D; ++k) {
        length2 += normal[k] * normal[k];
        to_centre += normal[k] * (centre[k] - a[k]);
        to_apex += normal[k] * (apex[k] - a[k]);
      }
      if (length2 == 0) continue;
      const double distance = (to_apex > 0 ? -to_centre : to_centre) / std::sqrt(length2);
      largest = std::max(largest, std::sqrt(r2) + distance);
    }
    return largest;
  }

  bool vertex_on_boundary(int site) const { return site < n_ && boundary_facets_at_[site] > 0; }

  bool edge_on_boundary(Cell_handle cell, int i, int j) const {
    return any_cell_around_edge<Traits>(triangulation_, cell, i, j,
                                        [&](Cell_handle c) { return is_outside(c); });
  }

  bool can_remove(Cell_handle cell) const {
    int opposite[D + 1];
    int k = 0;
    for (int i = 0; i <= D; ++i) {
      if (is_outside(cell->neighbor(i))) opposite[k++] = i;
    }
    if (k == 1) return !vertex_on_boundary(cell->vertex(opposite[0])->info());
    if (D == 3 && k == 2) return !edge_on_boundary(cell, opposite[0], opposite[1]);
    return false;
  }

  const Triangulation& triangulation_;
  Reconstruction<D>& result_;
  int n_;
  std::vector<char> outside_;
  std::vector<int> boundary_facets_at_;  // per sample: boundary facets through it
  std::priority_queue<Entry> queue_;
};

template <class Traits>
void run_boissonnat_method(const typename Traits::Triangulation& triangulation,
                           Reconstruction<Traits::dimension>& result, Stage_clock& clock) {
  clock.start("sculpting");
  Boissonnat_sculpting<Traits> sculpting(triangulation, result);
  sculpting.run(clock);
  result.stats.carved_cells = result.carving.events.size();
  const auto in_solid = [&](typename Traits::Cell_handle cell) {
    return !sculpting.is_outside(cell);
  };
  clock.start("solid");
  collect_solid<Traits>(triangulation, in_solid, result);
  clock.start("surface");
  collect_skin<Traits>(triangulation, in_solid, result);
}

}  // namespace sculpt
