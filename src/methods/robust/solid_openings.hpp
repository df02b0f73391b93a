// SPDX-License-Identifier: GPL-3.0-or-later
// The robust method's carving (manifold_carving.hpp) changes the solid's topology only here.
// Removing one cell at a time by Boissonnat's condition (carved_solid.hpp) never does: a torus
// stays filled, its hole a wall of outer cells that cannot be removed one at a time, and a
// cavity is never reached from the outside. Three steps remove outer cells several at once:
//   - a cavity, a group of outer cells enclosed by the solid, is opened at one cell when most
//     samples on it have their outer pole inside it;
//   - a group of outer cells that touches the outside is removed whole (a handle opens), or,
//     where noise spoils the manifold at a few of its vertices, all but its cells there;
//   - a web of outer cells with no free edge to carve from is punched through at a cell and the
//     outer cells around the vertex or edge that blocks it.
// Each goes only where the surface stays a 2-manifold at every vertex it touches, no sample
// leaves the solid and no small piece of the solid is cut off that is not a part of its own.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../../core/cells_around_edge.hpp"
#include "piece_evidence.hpp"
#include "spoilt_groups.hpp"

namespace sculpt {

template <class Traits>
class Solid_openings : public Spoilt_groups<Traits> {
 public:
  using Spoilt_groups<Traits>::Spoilt_groups;

 protected:
  using Base = Spoilt_groups<Traits>;
  static constexpr int D = Traits::dimension;
  using Base::carve_queue;
  using Base::fewest_euler_change_of_a_spoilt_group;
  using Base::is_outside;
  using Base::judged_outer;
  using Base::judged_reason;
  using Base::manifold_at;
  using Base::outside_;
  using Base::outside_cells_at_;
  using Base::outside_facets;
  using Base::push_if_outer;
  using Base::record_removal;
  using Base::removed_;
  using Base::result_;
  using Base::sample_count_;
  using Base::set_outside;
  using Base::solid_cells_at_;
  using Base::star_;
  using Base::tick_;
  using Base::triangulation_;
  using Base::unchanged_since;
  using Base::without_spoilt_vertices;
  using typename Base::Cell_handle;
  using typename Base::Vertex_handle;

  // A group removal must not cut off a piece of the solid with fewer cells.
  static constexpr std::size_t small_piece = 256;

  // How many samples have this cell as their outer pole: a sample's poles are cells around it,
  // so only the cell's own vertices can.
  int outer_pole_of(Cell_handle cell) const {
    int count = 0;
    for (int i = 0; i <= D; ++i) {
      const int s = cell->vertex(i)->info();
      if (s >= sample_count_) continue;
      for (int q : {result_.poles.positive_pole[s], result_.poles.negative_pole[s]}) {
        count += q >= 0 && result_.propagation.labels[q] == Label::outer &&
                 static_cast<int>(result_.poles.poles[q].cell) == cell->info();
      }
    }
    return count;
  }

  // The judged-outer cells still in the solid (fewer with every removal).
  const std::vector<Cell_handle>& outer_cells_left() {
    outer_left_.erase(std::remove_if(outer_left_.begin(), outer_left_.end(),
                                     [&](Cell_handle cell) { return is_outside(cell); }),
                      outer_left_.end());
    return outer_left_;
  }

  // The connected group of outer cells still in the solid that `start` belongs to, each marked
  // with a new mark (returned); `enclosed` says whether none of them touches the outside.
  int outer_group(Cell_handle start, std::vector<Cell_handle>& group, bool& enclosed) {
    if (group_mark_.size() != outside_.size()) group_mark_.assign(outside_.size(), 0);
    const int mark = ++group_counter_;
    group.clear();
    stack_.assign(1, start);
    group_mark_[start->info()] = mark;
    enclosed = true;
    while (!stack_.empty()) {  // depth first: the order cells are tried and carved around
      const Cell_handle cell = stack_.back();
      stack_.pop_back();
      group.push_back(cell);
      for (int i = 0; i <= D; ++i) {
        const Cell_handle neighbour = cell->neighbor(i);
        if (is_outside(neighbour)) {
          enclosed = false;
          continue;
        }
        if (!judged_outer(neighbour) || group_mark_[neighbour->info()] == mark) continue;
        group_mark_[neighbour->info()] = mark;
        stack_.push_back(neighbour);
      }
    }
    return mark;
  }

  // Carving from the outside never reaches a cavity: the hole of an annulus (2D), the inside of a
  // hollow part. A group of outer cells enclosed by the solid is a cavity when most samples on it
  // (at least half) have their outer pole inside it: the labelling saw the medial balls of a
  // hollow there. A pocket left by a few mislabelled poles has few (femur: 5 of its samples, the
  // annulus: all 60). The cavity is opened at the cell that is the outer pole of most samples;
  // removing it makes a new boundary, a sphere (circle) around it, which is a manifold when none
  // of its vertices is on the surface yet. Carving goes on from there.
  void open_cavities() {
    const int first_mark = group_counter_ + 1;
    std::vector<Cell_handle> group;
    std::vector<int> samples;
    for (Cell_handle start : std::vector<Cell_handle>(outer_cells_left())) {
      if (is_outside(start) || (!group_mark_.empty() && group_mark_[start->info()] >= first_mark)) {
        continue;  // carved since, or in a group already seen
      }
      bool enclosed = false;
      const int mark = outer_group(start, group, enclosed);
      if (!enclosed) continue;
      samples.clear();
      Cell_handle opening = start;
      for (Cell_handle cell : group) {
        if (outer_pole_of(cell) > outer_pole_of(opening)) {
          opening = cell;
        }
        for (int i = 0; i <= D; ++i) samples.push_back(cell->vertex(i)->info());
      }
      std::sort(samples.begin(), samples.end());
      samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
      std::size_t pointing = 0;
      for (int s : samples) {
        bool points_in = false;
        for (int q : {result_.poles.positive_pole[s], result_.poles.negative_pole[s]}) {
          if (q < 0 || result_.propagation.labels[q] != Label::outer) continue;
          points_in = points_in || group_mark_[result_.poles.poles[q].cell] == mark;
        }
        pointing += points_in;
      }
      if (2 * pointing < samples.size()) continue;
      bool clear = true;
      for (int i = 0; i <= D && clear; ++i) {
        const int s = opening->vertex(i)->info();
        clear = outside_cells_at_[s] == 0 && solid_cells_at_[s] > 1;
      }
      if (!clear) continue;
      set_outside(opening, true);
      record_opening({opening}, Opening_kind::cavity, euler_change_of_removal({opening}));
      record_removal(opening, judged_reason(opening));
      for (int i = 0; i <= D; ++i) push_if_outer(opening->neighbor(i));
      carve_queue();
    }
  }

  // Sculpting by Boissonnat's condition never changes the topology of the solid: a torus stays
  // filled, its hole a wall of outer cells that cannot be removed one at a time. Each connected
  // group of outer cells still in the solid is tried as a whole: it goes if the surface stays a
  // manifold at every vertex of the group and no sample leaves the solid; else, spoilt at a few
  // vertices only, without its cells there.
  void open_handles() {
    std::vector<Cell_handle> group;
    for (int round = 0; round < 4; ++round) {
      bool opened = false;
      const int first_mark = group_counter_ + 1;
      for (Cell_handle start : std::vector<Cell_handle>(outer_cells_left())) {
        if (is_outside(start) ||
            (!group_mark_.empty() && group_mark_[start->info()] >= first_mark)) {
          continue;
        }
        bool enclosed = false;
        outer_group(start, group, enclosed);
        if (enclosed) continue;
        if (try_remove_group(group, Opening_kind::group)) {
          opened = true;
          continue;
        }
        // Noise spoils the manifold at a few of a group's vertices (a torus's hole through
        // samples noisy by a tenth of their spacing): the rest of the group goes (see
        // without_spoilt_vertices).
        if (without_spoilt_vertices(group) &&
            try_remove_group(group, Opening_kind::group, nullptr, nullptr,
                             fewest_euler_change_of_a_spoilt_group)) {
          opened = true;
        }
      }
      if (!opened) break;
    }
  }

  // A web of outer cells spanning a loop of the shape (between the strands of a knot) has no free
  // edge to carve from: its first removable cell is blocked by a vertex (or edge) already on the
  // surface on the web's other side. Removing that cell together with the outer cells around the
  // blocking vertex (edge) punches a hole through the web at once; it goes if the surface stays a
  // manifold there, and Boissonnat's carving then widens the hole.
  //
  // A punch never opens a handle, though (in 2D a group that touches the outside cannot open a
  // hole: holes open as cavities): the tunnel it would make is the star of
  // one vertex or edge, where the web is one sample thin, thinner than the samples can vouch for
  // (two limbs that touch, a noisy corner, a wall of a sparse CAD part). Handles open where a
  // whole group of outer cells goes at once (open_handles), a tunnel the poles see whole. The web
  // stays, and where the punch was refused is kept (Carving_stage::refused_handles). Measured on
  // CGAL's 56 closed meshes: right topology on 36 (33 with such punches), homer, bull and handle
  // among them; couplingdown (a CAD part whose thin real handles only punches opened) and femur
  // lose theirs. Well-sampled shapes (tori, knots, the elephant) open every handle as a group.
  void punch_through() {
    std::vector<Cell_handle> group;
    for (int round = 0; round < 4; ++round) {
      bool punched = false;
      for (Cell_handle cell : std::vector<Cell_handle>(outer_cells_left())) {
        if (is_outside(cell)) continue;
        // Nothing changed around the cell (its faces, the cells at its vertices) and around the
        // vertices that failed since this punch last failed: it would fail again, the same way.
        const auto failed = failed_punches_.find(cell->info());
        if (failed != failed_punches_.end()) {
          bool unchanged = true;
          for (Vertex_handle v : failed->second.at)
            unchanged = unchanged && unchanged_since(v, failed->second.tick);
          for (int i = 0; i <= D; ++i)
            unchanged = unchanged && unchanged_since(cell->vertex(i), failed->second.tick);
          if (unchanged) continue;
        }
        int opposite[D + 1];
        const int k = outside_facets(cell, opposite);
        if (k == 0 || k >= D) continue;
        group.assign(1, cell);
        const auto add = [&](Cell_handle c) {
          if (c != cell && !is_outside(c) && judged_outer(c)) group.push_back(c);
        };
        if (k == 1) {
          star_.clear();
          Traits::incident_cells(triangulation_, cell->vertex(opposite[0]), star_);
          for (Cell_handle c : star_) add(c);
        } else if constexpr (D == 3) {
          const auto first = triangulation_.incident_cells(cell, opposite[0], opposite[1]);
          auto c = first;
          do add(c);
          while (++c != first);
        }
        Vertex_handle failed_at{};
        bool opens_handle = false;
        const bool removed =
            try_remove_group(group, Opening_kind::punch, &failed_at, &opens_handle);
        if (!opens_handle) refused_punches_.erase(cell->info());
        if (removed) {
          punched = true;
        } else if (opens_handle) {
          // The change of topology reads the cells around every vertex of the group: tried again
          // once one of them changes.
          refused_punches_.emplace(cell->info(), cell);
          failed_punches_[cell->info()] = {tick_, group_vertices_};
        } else if (failed_at != Vertex_handle{}) {
          failed_punches_[cell->info()] = {tick_, {failed_at}};
        }
      }
      if (!punched) break;
    }
  }

  // Whether removing `group` (already set outside) cut a small piece off the solid: a collapse
  // never disconnects, a group removal can. From a solid neighbour of the group a search through
  // the solid either grows past small_piece cells (whatever it is in is large: a real part), or
  // stops short, a piece of its own: the only piece when it holds every neighbour (nothing was
  // cut off), else a small piece cut off, refused unless the labelling says it is a part in its
  // own right (piece_evidence.hpp: a separate curve, a small separate part). A neighbour inside a
  // piece found before is in that piece, and a search reaching a large one is as large.
  bool cuts_off_small_piece(const std::vector<Cell_handle>& group) {
    enum : std::uint8_t { unreached = 0, in_this_search = 1, in_large_piece = 2, in_own_part = 3 };
    std::vector<Cell_handle> neighbours;
    for (Cell_handle cell : group) {
      for (int i = 0; i <= D; ++i) {
        if (!is_outside(cell->neighbor(i))) neighbours.push_back(cell->neighbor(i));
      }
    }
    if (reached_.size() != outside_.size()) reached_.assign(outside_.size(), unreached);
    large_pieces_.clear();
    own_parts_.clear();
    const auto search_small_piece = [&](Cell_handle from) {  // false: from is in a large piece
      piece_.assign(1, from);
      reached_[from->info()] = in_this_search;
      for (std::size_t next = 0; next < piece_.size(); ++next) {
        if (piece_.size() >= small_piece) return false;
        for (int i = 0; i <= D; ++i) {
          const Cell_handle neighbour = piece_[next]->neighbor(i);
          if (is_outside(neighbour)) continue;
          const std::uint8_t mark = reached_[neighbour->info()];
          if (mark == in_large_piece) return false;
          if (mark == in_this_search) continue;
          reached_[neighbour->info()] = in_this_search;
          piece_.push_back(neighbour);
        }
      }
      return true;
    };
    bool cut = false;
    for (Cell_handle from : neighbours) {
      if (reached_[from->info()] != unreached) continue;
      if (!search_small_piece(from)) {
        for (Cell_handle cell : piece_) reached_[cell->info()] = in_large_piece;
        large_pieces_.insert(large_pieces_.end(), piece_.begin(), piece_.end());
        continue;
      }
      const bool whole = std::all_of(neighbours.begin(), neighbours.end(), [&](Cell_handle other) {
        return reached_[other->info()] == in_this_search;
      });
      if (whole) break;  // the only piece: nothing cut off
      if (!is_part_of_its_own(piece_)) {
        cut = true;
        break;
      }
      for (Cell_handle cell : piece_) reached_[cell->info()] = in_own_part;
      own_parts_.insert(own_parts_.end(), piece_.begin(), piece_.end());
    }
    // Only the cells searched carry marks: unmark them.
    for (Cell_handle cell : piece_) reached_[cell->info()] = unreached;
    for (Cell_handle cell : large_pieces_) reached_[cell->info()] = unreached;
    for (Cell_handle cell : own_parts_) reached_[cell->info()] = unreached;
    piece_.clear();
    return cut;
  }

  // A small piece of the solid (its cells, marked in reached_ by the search that found them)
  // that holds the inner poles of most of its samples.
  bool is_part_of_its_own(const std::vector<Cell_handle>& piece) {
    std::vector<int> samples;
    for (Cell_handle cell : piece) {
      for (int i = 0; i <= D; ++i) {
        if (cell->vertex(i)->info() < sample_count_) samples.push_back(cell->vertex(i)->info());
      }
    }
    std::sort(samples.begin(), samples.end());
    samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
    const std::uint8_t mark = reached_[piece.front()->info()];
    return holds_inner_poles_of_most(result_, samples,
                                     [&](std::size_t cell) { return reached_[cell] == mark; });
  }

  // `failed_at`, when given, is set to the vertex whose test failed (left alone when the group
  // would cut a piece off).
  // `opens_handle`, when given, is set when a punch was refused because it would open a handle.
  bool try_remove_group(const std::vector<Cell_handle>& group, Opening_kind kind,
                        Vertex_handle* failed_at = nullptr, bool* opens_handle = nullptr,
                        int fewest_change = INT_MIN) {
    // Callers pass groups that touch the outside (pockets inside the solid are cavities' business).
    for (Cell_handle cell : group) set_outside(cell, true);
    // Each vertex of the group once: the cells around a vertex all share it (punch_through's
    // groups), and a vertex's test walks all its cells.
    group_vertices_.clear();
    for (Cell_handle cell : group) {
      for (int i = 0; i <= D; ++i) group_vertices_.push_back(cell->vertex(i));
    }
    std::sort(group_vertices_.begin(), group_vertices_.end());
    group_vertices_.erase(std::unique(group_vertices_.begin(), group_vertices_.end()),
                          group_vertices_.end());
    bool fine = true;
    for (std::size_t j = 0; j < group_vertices_.size() && fine; ++j) {
      const Vertex_handle v = group_vertices_[j];
      fine = solid_cells_at_[v->info()] > 0 && manifold_at(v);
      if (!fine && failed_at) *failed_at = v;
    }
    if (fine) fine = !cuts_off_small_piece(group);
    const int change = fine ? euler_change_of_removal(group) : 0;
    if (fine && change < fewest_change) fine = false;
    if (fine && kind == Opening_kind::punch && change < 0) {
      fine = false;
      if (opens_handle) *opens_handle = true;
    }
    if (!fine) {
      for (Cell_handle cell : group) set_outside(cell, false);
      return false;
    }
    record_opening(group, kind, change);
    for (Cell_handle cell : group) record_removal(cell, judged_reason(cell));
    // Removing the group can make Boissonnat's condition hold for outer cells next to it.
    for (Cell_handle cell : group) {
      for (int i = 0; i <= D; ++i) push_if_outer(cell->neighbor(i));
    }
    carve_queue();
    return true;
  }

  // An opening (`cells`, already outside, not yet recorded as removed) and the change it made
  // to the solid's Euler characteristic.
  void record_opening(const std::vector<Cell_handle>& cells, Opening_kind kind, int change) {
    Carving_opening opening;
    opening.first_event = static_cast<std::uint32_t>(removed_);
    opening.cells = static_cast<std::uint32_t>(cells.size());
    opening.kind = kind;
    opening.euler_change = change;
    result_.carving.openings.push_back(opening);
    if (opening.euler_change < 0)
      result_.stats.carved_handles += std::size_t(-opening.euler_change);
  }

  // The change of the solid's Euler characteristic (vertices - edges + faces - cells, in 3D)
  // when `cells` (already outside) left it: minus the alternating count of their faces that no
  // solid cell holds any more. Counted around the cells only: a few tests per cell.
  int euler_change_of_removal(const std::vector<Cell_handle>& cells) const {
    std::set<int> vertices;
    std::set<std::pair<int, int>> edges;  // 3D: the edges; in 2D the facets are the edges
    std::set<std::array<int, D>> facets;
    const auto solid = [&](Cell_handle cell) { return !is_outside(cell); };
    for (Cell_handle cell : cells) {
      for (int i = 0; i <= D; ++i) {
        const int v = cell->vertex(i)->info();
        if (solid_cells_at_[v] == 0) vertices.insert(v);
        if (is_outside(cell->neighbor(i))) {
          std::array<int, D> facet;
          for (int j = 0, k = 0; j <= D; ++j) {
            if (j != i) facet[k++] = cell->vertex(j)->info();
          }
          std::sort(facet.begin(), facet.end());
          facets.insert(facet);
        }
        if constexpr (D == 3) {
          for (int j = i + 1; j <= D; ++j) {
            if (any_cell_around_edge<Traits>(triangulation_, cell, i, j, solid)) continue;
            const int a = cell->vertex(i)->info(), b = cell->vertex(j)->info();
            edges.insert({std::min(a, b), std::max(a, b)});
          }
        }
      }
    }
    const long cells_gone = static_cast<long>(cells.size());
    const long alternating =
        D == 3 ? long(vertices.size()) - long(edges.size()) + long(facets.size()) - cells_gone
               : long(vertices.size()) - long(facets.size()) + cells_gone;
    return static_cast<int>(-alternating);
  }

  // The cells whose punch was refused because it would open a handle, by number (those still in
  // the solid at the end are where the webs stayed).
  std::unordered_map<int, Cell_handle> refused_punches_;
  std::vector<Cell_handle> piece_, large_pieces_, own_parts_;
  std::vector<Vertex_handle> group_vertices_;
  // Per outer cell whose punch failed: the stamp then, and the vertex whose test failed (or, for
  // a punch refused as it would open a handle, every vertex of its group).
  struct Failed_punch {
    std::uint32_t tick;
    std::vector<Vertex_handle> at;
  };
  std::unordered_map<int, Failed_punch> failed_punches_;
  std::vector<std::uint8_t> reached_;    // per cell: reached by a search of cuts_off_small_piece
  std::vector<Cell_handle> outer_left_;  // judged outer and in the solid after the first carve
  std::vector<Cell_handle> stack_;
  std::vector<int> group_mark_;  // per cell: the outer group that last reached it
  int group_counter_ = 0;
};

}  // namespace sculpt
