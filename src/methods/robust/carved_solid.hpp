// SPDX-License-Identifier: GPL-3.0-or-later
// The solid that the robust method carves (manifold_carving.hpp), and the carving's one step.
//
// The solid is a set of cells of DT(S ∪ BBV): a flag per cell, and per sample the count of its
// cells in the solid and outside. A cell is removed when it touches the outside through k of
// its facets and the removal keeps the surface a 2-manifold (a closed curve in 2D), which is
// Boissonnat's condition for sculpting (1984): the part of the cell's boundary that touches the
// outside must be a disk. It is, unless the simplex spanned by the vertices opposite those k
// facets already touches the outside:
//   k = 1        its opposite vertex must not be on the surface (or the surface pinches there);
//   k = 2 (3D)   its opposite edge must not be on the surface (or the surface folds over it);
//   k >= D       always (the rest of its boundary is one facet shared with the solid).
// A removal must also leave every one of its samples on some solid cell, so that the surface
// interpolates them all. Such a removal is a collapse: it never changes the solid's topology.
// Cells judged outer are removed largest circumball first (as Boissonnat does), from a queue; a
// cell that cannot be removed now is queued again whenever a neighbour is removed.
// Removals of several cells at once (solid_openings.hpp) test the surface at each vertex
// instead (manifold_at).
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <queue>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/cells_around_edge.hpp"
#include "../../core/circumball_query.hpp"
#include "../../core/stage_clock.hpp"
#include "cell_classification.hpp"

namespace sculpt {

template <class Traits>
class Carved_solid {
 public:
  static constexpr int D = Traits::dimension;
  using Triangulation = typename Traits::Triangulation;
  using Cell_handle = typename Traits::Cell_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;

  // The judge's verdicts (cell_classification.hpp) are one byte a cell; whatever else the
  // carving needs of a cell (its circumradius, the samples whose outer pole it is) is computed
  // when asked, for the few cells that are asked about.
  Carved_solid(const Triangulation& triangulation, Reconstruction<D>& result,
               const Cell_judge<Traits>& judge, const Stage_clock& clock)
      : triangulation_(triangulation),
        result_(result),
        judge_(judge),
        clock_(clock),
        sample_count_(static_cast<int>(result.sample_count())),
        outside_(result.delaunay.cell_count, 0) {}

  // How many cells were removed.
  std::size_t removed() const { return removed_; }

  bool is_outside(Cell_handle cell) const {
    return triangulation_.is_infinite(cell) || outside_[cell->info()];
  }

  bool is_sample(Vertex_handle v) const {
    return !triangulation_.is_infinite(v) && v->info() < sample_count_;
  }

  bool judged_outer(Cell_handle cell) const { return judge_.verdict(cell) != 0; }

  // The squared circumradius, rounded to a float: the carving order.
  float radius2(Cell_handle cell) const {
    return static_cast<float>(squared_circumradius<Traits>(
        cell, Traits::from_cgal(Traits::circumcenter(triangulation_, cell))));
  }

  Carve_reason judged_reason(Cell_handle cell) const {
    return static_cast<Carve_reason>(judge_.verdict(cell) - 1);
  }

  int outside_facets(Cell_handle cell, int opposite[]) const {
    int k = 0;
    for (int i = 0; i <= D; ++i) {
      if (is_outside(cell->neighbor(i))) opposite[k++] = i;
    }
    return k;
  }

  bool vertex_on_surface(Vertex_handle v) const { return outside_cells_at_[v->info()] > 0; }

  bool edge_on_surface(Cell_handle cell, int i, int j) const {
    return any_cell_around_edge<Traits>(triangulation_, cell, i, j,
                                        [&](Cell_handle c) { return is_outside(c); });
  }

  // Boissonnat's condition, and no sample left off the solid.
  bool can_remove(Cell_handle cell) const {
    for (int i = 0; i <= D; ++i) {
      if (solid_cells_at_[cell->vertex(i)->info()] <= 1) return false;
    }
    int opposite[D + 1];
    const int k = outside_facets(cell, opposite);
    if (k == 0) return false;
    if (k >= D) return true;
    if (k == 1) return !vertex_on_surface(cell->vertex(opposite[0]));
    return !edge_on_surface(cell, opposite[0], opposite[1]);  // k = 2 in 3D
  }

  void set_outside(Cell_handle cell, bool outside) {
    outside_[cell->info()] = outside;
    const int change = outside ? 1 : -1;
    for (int i = 0; i <= D; ++i) {
      const int s = cell->vertex(i)->info();
      solid_cells_at_[s] -= change;
      outside_cells_at_[s] += change;
    }
  }

  void remove(Cell_handle cell, Carve_reason reason) {
    set_outside(cell, true);
    record_removal(cell, reason);
  }

  // The events name cells of the first triangulation: kept with its cells (the viewer, the
  // tests), only counted without them (the command line: 40 MB on a 1M-point torus).
  void record_removal(Cell_handle cell, Carve_reason reason) {
    ++removed_;
    if (result_.options.keep_triangulations)
      result_.carving.events.push_back({cell->info(), reason});
    if (!stamp_.empty()) stamp_around(cell);
  }

  bool unchanged_since(Vertex_handle v, std::uint32_t tick) const {
    return stamp_[v->info()] <= tick;
  }

  // A cell is queued at most once at a time: a removal next to a queued cell changes what its
  // pending entry will find, so a second entry would only be popped and tried again.
  void push_if_outer(Cell_handle cell) {
    if (!is_outside(cell) && judged_outer(cell) && !queued_[cell->info()]) {
      queued_[cell->info()] = 1;
      queue_.push({radius2(cell), cell->info(), cell});
    }
  }

  void carve_queue() {
    while (!queue_.empty()) {
      const Cell_handle cell = queue_.top().cell;
      queue_.pop();
      queued_[cell->info()] = 0;
      if (is_outside(cell) || !can_remove(cell)) continue;
      remove(cell, judged_reason(cell));
      for (int i = 0; i <= D; ++i) push_if_outer(cell->neighbor(i));
    }
  }

  // The surface is a 2-manifold at a vertex when its facets around the vertex form one fan:
  // 3D, the link edges (the facets' sides opposite v) make one cycle; 2D, two edges meet at v.
  // A vertex on no facet passes.
  bool manifold_at(Vertex_handle v) {
    star_.clear();
    Traits::incident_cells(triangulation_, v, star_);
    link_.clear();
    for (Cell_handle cell : star_) {
      if (is_outside(cell)) continue;
      const int at = cell->index(v);
      for (int i = 0; i <= D; ++i) {
        if (i == at || !is_outside(cell->neighbor(i))) continue;
        std::array<int, 2> edge{-1, -1};
        for (int j = 0, k = 0; j <= D; ++j) {
          if (j != at && j != i) edge[k++] = cell->vertex(j)->info();
        }
        link_.push_back(edge);
      }
    }
    if (link_.empty()) return true;
    if constexpr (D == 2) {
      return link_.size() == 2;
    } else {
      // One cycle: every link vertex has degree 2, and walking from one edge visits them all.
      auto& ends = link_ends_;
      ends.clear();
      for (const auto& e : link_) {
        ends.push_back({e[0], e[1]});
        ends.push_back({e[1], e[0]});
      }
      std::sort(ends.begin(), ends.end());
      for (std::size_t i = 0; i < ends.size(); i += 2) {
        if (i + 1 >= ends.size() || ends[i].first != ends[i + 1].first) return false;
        if (i + 2 < ends.size() && ends[i + 2].first == ends[i].first) return false;
      }
      const auto next = [&](int at, int from) {
        const auto it = std::lower_bound(ends.begin(), ends.end(), std::make_pair(at, INT_MIN));
        return it->second == from ? (it + 1)->second : it->second;
      };
      const int start = link_[0][0];
      int previous = start, current = link_[0][1];
      std::size_t length = 1;
      while (current != start && length <= link_.size()) {
        const int after = next(current, previous);
        previous = current;
        current = after;
        ++length;
      }
      return length == link_.size();
    }
  }

  bool buried(int sample) const {
    return solid_cells_at_[sample] > 0 && outside_cells_at_[sample] == 0;
  }

  // The carving's progress, never going back (an undone flood's, then the carving's).
  void report(double fraction) {
    if (fraction <= reported_) return;
    reported_ = std::min(1.0, fraction);
    clock_.report(reported_);
  }

  // The solid is the hull: every all-sample cell; each sample's cells in it and outside counted
  // (the carving cell by cell reads the counts).
  void start_from_hull() {
    solid_cells_at_.assign(sample_count_, 0);
    outside_cells_at_.assign(sample_count_, 0);
    for (auto cell : Traits::finite_cells(triangulation_)) {
      bool all_samples = true;
      for (int i = 0; i <= D; ++i) all_samples = all_samples && is_sample(cell->vertex(i));
      outside_[cell->info()] = !all_samples;
      for (int i = 0; i <= D; ++i) {
        if (!is_sample(cell->vertex(i))) continue;
        ++(all_samples ? solid_cells_at_ : outside_cells_at_)[cell->vertex(i)->info()];
      }
    }
  }

 protected:
  // Largest circumball first; among equal ones (cospherical samples) the lowest cell index, so
  // that the order does not depend on the queue's history.
  struct Entry {
    float radius2;
    int index;
    Cell_handle cell;
    bool operator<(const Entry& other) const {
      return radius2 < other.radius2 || (radius2 == other.radius2 && index > other.index);
    }
  };

  // A removal stamps the cell's vertices: a vertex's stamp moves whenever a cell around it
  // changes. That is all a vertex's manifold test (manifold_at) and its count of solid cells read
  // (the neighbour across a facet at v is around v too); a punch at a cell reads the cell's
  // neighbours, each sharing all but one of its vertices, and the cells around one of its
  // vertices or edges; its change of topology, the cells around every vertex of its group.
  void stamp_around(Cell_handle cell) {
    ++tick_;
    for (int i = 0; i <= D; ++i) stamp_[cell->vertex(i)->info()] = tick_;
  }

  const Triangulation& triangulation_;
  Reconstruction<D>& result_;
  const Cell_judge<Traits>& judge_;
  const Stage_clock& clock_;
  int sample_count_;
  std::vector<std::uint8_t> outside_;
  std::vector<std::uint8_t> queued_;  // per cell: an entry of it is in the queue
  std::size_t removed_ = 0;           // cells removed (the events, when they are kept)
  double reported_ = 0;               // the carving's progress so far
  // Per sample (counted by start_from_hull, not by a flood): incident cells still in the solid,
  // and outside.
  std::vector<int> solid_cells_at_;
  std::vector<int> outside_cells_at_;
  std::priority_queue<Entry> queue_;
  std::vector<Cell_handle> star_;  // the cells around a vertex, as a test walks them
  // The change stamps (stamp_around), per site; empty in the flood, which needs none.
  std::vector<std::uint32_t> stamp_;
  std::uint32_t tick_ = 0;
  std::vector<std::array<int, 2>> link_;
  std::vector<std::pair<int, int>> link_ends_;
};

}  // namespace sculpt
