// SPDX-License-Identifier: GPL-3.0-or-later
// The last step of the robust method's carving (manifold_carving.hpp): samples left buried
// inside the solid are brought onto the surface. A sample is buried when its surface passed
// over it, as when a quad of nearly cospherical samples takes the other diagonal: every cell
// around it is solid, and the surface no longer interpolates it. One more cell of its own is
// removed, of those Boissonnat's condition lets go (carved_solid.hpp) the one whose longest edge
// is shortest, or else a short path of cells is dug down to it. Not the largest: on a smoothed
// noisy scan the largest is often a tetrahedron reaching across the part to the far side's
// surface, and removing it dips the surface from there down to the one sample, a spike through
// the part (CGAL's fandisk and double-torus-example scanned: 5% and 4% of the diagonal from
// the part, 1.4% and 1.6% with the shortest; tests/cgal_meshes_test.cpp, Noisy_scan).
#pragma once

#include <algorithm>
#include <unordered_set>
#include <utility>
#include <vector>

#include "carved_solid.hpp"

namespace sculpt {

template <class Traits>
class Buried_samples : public Carved_solid<Traits> {
 public:
  using Carved_solid<Traits>::Carved_solid;

 protected:
  using Base = Carved_solid<Traits>;
  static constexpr int D = Traits::dimension;
  using Base::buried;
  using Base::can_remove;
  using Base::is_outside;
  using Base::is_sample;
  using Base::outside_facets;
  using Base::radius2;
  using Base::record_removal;
  using Base::remove;
  using Base::set_outside;
  using Base::star_;
  using Base::triangulation_;
  using typename Base::Cell_handle;
  using typename Base::Vertex_handle;

  void expose_buried_samples() {
    std::vector<Vertex_handle> waiting;
    for (auto v : Traits::finite_vertices(triangulation_)) {
      if (is_sample(v) && buried(v->info())) waiting.push_back(v);
    }
    // A removal can make a deeper sample reachable: a few rounds, while they help.
    for (int round = 0; round < 8 && !waiting.empty(); ++round) {
      std::vector<Vertex_handle> still;
      for (Vertex_handle v : waiting) {
        if (!buried(v->info())) continue;
        star_.clear();
        Traits::incident_cells(triangulation_, v, star_);
        Cell_handle best{};
        double best_edge2 = -1;
        for (Cell_handle cell : star_) {
          if (triangulation_.is_infinite(cell) || is_outside(cell) || !can_remove(cell)) continue;
          const double edge2 = longest_edge2(cell);
          if (best_edge2 < 0 || edge2 < best_edge2) {
            best = cell;
            best_edge2 = edge2;
          }
        }
        if (best_edge2 >= 0) {
          remove(best, Carve_reason::exposes_sample);
        } else if (!dig_to(star_)) {
          still.push_back(v);
        }
      }
      if (still.size() == waiting.size()) break;
      waiting.swap(still);
    }
  }

  // The square of a cell's longest edge: how far from its samples the surface goes when the
  // cell is removed and its other facets take the place of the one it had on the surface.
  double longest_edge2(Cell_handle cell) const {
    double longest = 0;
    for (int i = 0; i <= D; ++i) {
      for (int j = i + 1; j <= D; ++j) {
        const auto a = Traits::from_cgal(cell->vertex(i)->point());
        const auto b = Traits::from_cgal(cell->vertex(j)->point());
        double d2 = 0;
        for (int k = 0; k < D; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
        longest = std::max(longest, d2);
      }
    }
    return longest;
  }

  // A sample buried under the surface by more than one cell (under a nearly flat quad whose
  // other diagonal won, up to a spacing or so deep): no cell of its own touches the outside.
  // A short path of solid cells from the outside down to one of them, each removable when the
  // one before it is gone, is removed whole (each step a collapse, by Boissonnat's condition:
  // the topology stays, the surface dents down to the sample); a path that stops is put back.
  // Paths are searched breadth first from the sample's cells, at most dig_depth cells long.
  // `cells_of_sample`: the cells around the buried sample.
  static constexpr int dig_depth = 6;
  bool dig_to(const std::vector<Cell_handle>& cells_of_sample) {
    // Breadth first through solid cells: each cell found, with the index of the one it was
    // reached from (-1: a cell of the sample).
    std::vector<std::pair<Cell_handle, int>> found;
    std::unordered_set<int> seen;
    for (Cell_handle cell : cells_of_sample) {
      if (is_outside(cell)) continue;
      seen.insert(cell->info());
      found.push_back({cell, -1});
    }
    std::size_t level_begin = 0;
    for (int depth = 1; depth <= dig_depth; ++depth) {
      const std::size_t level_end = found.size();
      for (std::size_t f = level_begin; f < level_end; ++f) {
        Cell_handle cell = found[f].first;
        if (depth > 1 && outside_facets_count(cell) > 0 && try_path(found, static_cast<int>(f)))
          return true;
        if (depth == dig_depth) continue;
        for (int i = 0; i <= D; ++i) {
          Cell_handle next = cell->neighbor(i);
          if (is_outside(next)) continue;
          if (seen.insert(next->info()).second) found.push_back({next, static_cast<int>(f)});
        }
      }
      level_begin = level_end;
    }
    return false;
  }

  int outside_facets_count(Cell_handle cell) const {
    int opposite[D + 1];
    return outside_facets(cell, opposite);
  }

  // Removes the path from found[last] (on the surface) back to a cell of the sample, each cell
  // removable in turn; or nothing.
  bool try_path(const std::vector<std::pair<Cell_handle, int>>& found, int last) {
    std::vector<Cell_handle> path;
    for (int f = last; f >= 0; f = found[f].second) path.push_back(found[f].first);
    std::size_t done = 0;
    for (; done < path.size(); ++done) {
      if (!can_remove(path[done])) break;
      set_outside(path[done], true);
    }
    if (done == path.size()) {
      for (Cell_handle cell : path) record_removal(cell, Carve_reason::exposes_sample);
      return true;
    }
    while (done > 0) set_outside(path[--done], false);
    return false;
  }
};

}  // namespace sculpt
