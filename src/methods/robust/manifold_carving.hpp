// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 6b of the robust method: carve the hull of the samples from the outside in, one cell at
// a time, keeping the surface a 2-manifold (a closed curve in 2D) after every removal.
//
// The solid starts as every all-sample cell of DT(S ∪ BBV) (the hull of the samples); the
// outside is every other cell. A cell judged outer (cell_classification.hpp) is removed when it
// touches the outside through k of its facets and the removal keeps the surface a manifold,
// which is Boissonnat's condition for sculpting (1984): the part of the cell's boundary that
// touches the outside must be a disk. It is, unless the simplex spanned by the vertices opposite
// those k facets already touches the outside:
//   k = 1        its opposite vertex must not be on the surface (or the surface pinches there);
//   k = 2 (3D)   its opposite edge must not be on the surface (or the surface folds over it);
//   k >= D       always (the rest of its boundary is one facet shared with the solid).
// A removal must also leave every one of its samples on some solid cell, so that the surface
// interpolates them all. Cells are removed largest circumball first (as Boissonnat does); a cell
// that cannot be removed now is tried again whenever a neighbour is removed. Outer cells that
// never can be stay in the solid and are counted.
//
// Last, samples left buried inside the solid (their surface passed over them, as when a quad of
// nearly cospherical samples takes the other diagonal) are exposed by removing one more cell
// of theirs, when that keeps the manifold, or else a short path of cells dug down to them.
//
// First, though, the carving tries a shortcut (Options::carve_by_flood): every outer cell the
// outside reaches through outer cells is removed at once, a flood. Until it stalls, the carving
// removes only such cells (an enclosed group, a cavity, it opens only if the group holds outer
// poles), so where the flood leaves a closed 2-manifold through every sample, no outer pole's
// cell in the solid and no piece smaller than a group removal may cut off, the carving ends
// there too, or stalls short of it with outer cells it cannot remove one group at a time (two
// groups each pinching the surface alone but not together; the rounds running out). The flood
// stands for it then, and the cells it never reached are never judged; otherwise it is undone
// and the carving runs. Measured: the same triangles where the flood stood (the built-in closed
// shapes, CGAL's knot1 and bunny00, random tori, the scan hotdogs), the carving stage in 60-70%
// of the time; an undone flood (noisy scans, CAD meshes) costs about a tenth of the carving.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <optional>
#include <queue>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "../../core/cells_around_edge.hpp"
#include "../../core/circumball_query.hpp"
#include "../../core/closed_skin_check.hpp"
#include "../../core/prefetch.hpp"
#include "../../core/solid_and_skin.hpp"
#include "../../core/stage_clock.hpp"
#include "../../core/union_find.hpp"
#include "cell_classification.hpp"
#include "piece_evidence.hpp"

namespace sculpt {

template <class Traits>
class Manifold_carving {
  static constexpr int D = Traits::dimension;
  using Triangulation = typename Traits::Triangulation;
  using Cell_handle = typename Traits::Cell_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;

 public:
  // The judge's verdicts (cell_classification.hpp) are one byte a cell; whatever else the
  // carving needs of a cell (its circumradius, the samples whose outer pole it is) is computed
  // when asked, for the few cells that are asked about.
  Manifold_carving(const Triangulation& triangulation, Reconstruction<D>& result,
                   const Cell_judge<Traits>& judge, const Stage_clock& clock)
      : triangulation_(triangulation),
        result_(result),
        judge_(judge),
        clock_(clock),
        sample_count_(static_cast<int>(result.sample_count())),
        outside_(result.delaunay.cell_count, 0) {}

  void run() {
    if (result_.options.carve_by_flood) {
      if (flood_stands_for_carving(mark_outside_hull())) return;
    } else {
      start_from_hull();
    }
    carve_outer_cells();
    for (auto cell : Traits::finite_cells(triangulation_)) {
      if (!is_outside(cell) && judged_outer(cell)) outer_left_.push_back(cell);
    }
    open_cavities();
    // Punching leaves fragments of webs (bridges between strands) that are whole groups again.
    for (int round = 0; round < 4; ++round) {
      const std::size_t before = removed_;
      open_handles();
      punch_through();
      if (removed_ == before) break;
    }
    expose_buried_samples();
    record_what_stayed();
  }

  // How many cells were removed.
  std::size_t removed() const { return removed_; }

  // The surface's check as a closed 2-manifold through every sample, when the flood stood (it
  // passed it): the topology follows from it without checking the surface again.
  std::optional<Skin_check> checked_skin() const {
    return result_.stats.carved_by_flood ? checked_skin_ : std::nullopt;
  }

  bool is_outside(Cell_handle cell) const {
    return triangulation_.is_infinite(cell) || outside_[cell->info()];
  }

  // Stage 7: the cells left in the solid.
  void collect_solid() const {
    if (!result_.options.keep_solid) {  // counted from the flags: no pass over the cells
      result_.stats.solid_cells =
          static_cast<std::size_t>(std::count(outside_.begin(), outside_.end(), std::uint8_t{0}));
      return;
    }
    sculpt::collect_solid<Traits>(
        triangulation_, [&](Cell_handle cell) { return !is_outside(cell); }, result_);
  }

  // Stage 8: the facets between the solid and the outside, facing the outside (the flood
  // collected them already when it stood).
  void collect_surface() const {
    if (result_.stats.carved_by_flood) return;
    sculpt::collect_skin<Traits>(
        triangulation_, [&](Cell_handle cell) { return !is_outside(cell); }, result_);
  }

 private:
  // A group removal must not cut off a piece of the solid with fewer cells.
  static constexpr std::size_t small_piece = 256;

  // A facet of the skin: facet i of the solid cell numbered c, key (D + 1) c + i, its sites
  // facing out.
  struct Skin_facet {
    std::uint32_t key;
    Facet<D> sites;
  };

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

  bool is_sample(Vertex_handle v) const {
    return !triangulation_.is_infinite(v) && v->info() < sample_count_;
  }
  bool judged_outer(Cell_handle cell) const { return judge_.verdict(cell) != 0; }

  // The squared circumradius, rounded to a float: the carving order.
  float radius2(Cell_handle cell) const {
    return static_cast<float>(squared_circumradius<Traits>(
        cell, Traits::from_cgal(Traits::circumcenter(triangulation_, cell))));
  }

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
  Carve_reason judged_reason(Cell_handle cell) const {
    return static_cast<Carve_reason>(judge_.verdict(cell) - 1);
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

  // The flood's start: the cells outside the hull, marked so, and returned: the infinite ones
  // and those with a box corner among their vertices. Found around the corners, the hull's
  // vertices, not in a pass over every cell; the flood keeps no count of cells per sample (its
  // skin check finds a sample left off), so only an undone flood pays for start_from_hull.
  std::vector<Cell_handle> mark_outside_hull() {
    std::vector<Cell_handle> outside;
    Traits::incident_cells(triangulation_, triangulation_.infinite_vertex(), outside);
    std::vector<Vertex_handle> corners;
    for (Cell_handle cell : outside) {
      for (int i = 0; i <= D; ++i) {
        const Vertex_handle v = cell->vertex(i);
        // (A sample rounded onto a face of the box lies on the hull too.)
        if (!triangulation_.is_infinite(v) && !is_sample(v)) corners.push_back(v);
      }
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    std::vector<Cell_handle> around;
    for (Vertex_handle corner : corners) {
      around.clear();
      Traits::incident_cells(triangulation_, corner, around);
      for (Cell_handle cell : around) {
        if (triangulation_.is_infinite(cell) || outside_[cell->info()]) continue;
        outside_[cell->info()] = 1;
        outside.push_back(cell);
      }
    }
    return outside;
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

  // A removal stamps the cell's vertices: a vertex's stamp moves whenever a cell around it
  // changes. That is all a vertex's manifold test (manifold_at) and its count of solid cells read
  // (the neighbour across a facet at v is around v too); a punch at a cell reads the cell's
  // neighbours, each sharing all but one of its vertices, and the cells around one of its
  // vertices or edges.
  void stamp_around(Cell_handle cell) {
    ++tick_;
    for (int i = 0; i <= D; ++i) stamp_[cell->vertex(i)->info()] = tick_;
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

  void carve_outer_cells() {
    queued_.assign(result_.delaunay.cell_count, 0);  // not before: the flood needs none
    stamp_.assign(result_.sites.size(), 0);
    // Every cell is judged here (most for the first time): the long part, which the progress
    // follows.
    const double cells = static_cast<double>(result_.delaunay.cell_count);
    std::size_t done = 0;
    for (auto cell : Traits::finite_cells(triangulation_)) {
      if (++done % 262144 == 0) report(double(done) / cells);
      if (is_outside(cell) || !judged_outer(cell)) continue;
      for (int i = 0; i <= D; ++i) {
        if (is_outside(cell->neighbor(i))) {
          push_if_outer(cell);
          break;
        }
      }
    }
    carve_queue();
  }

  // The shortcut (see the top): flood the outer cells from the outside, depth first, and keep
  // the result if it is where the carving was going; else undo it.
  bool flood_stands_for_carving(std::vector<Cell_handle> outside_hull) {
    // The cells of the outer poles, by number, for the pocket test of flood_is_the_carving.
    std::vector<int> pole_cells;
    const auto& poles = result_.poles;
    for (int s = 0; s < sample_count_; ++s) {
      for (int q : {poles.positive_pole[s], poles.negative_pole[s]}) {
        if (q < 0 || result_.propagation.labels[q] != Label::outer) continue;
        if (!poles.poles[q].convex) pole_cells.push_back(static_cast<int>(poles.poles[q].cell));
      }
    }
    std::sort(pole_cells.begin(), pole_cells.end());
    pole_cells.erase(std::unique(pole_cells.begin(), pole_cells.end()), pole_cells.end());
    // A cell is removed when it is found, so none is found twice; the stack holds removed cells
    // whose neighbours are still to be looked at.
    std::vector<Cell_handle> stack;
    // The flood's skin as it is found: a facet between a flooded cell and a neighbour judged
    // inner, which the flood never removes, or between the hull's outside and a cell the flood
    // left. Not a second pass over every solid cell's neighbours (on a 300k random torus, 3.5M
    // of them: 0.36 s).
    // (Keyed by 32 bits: beyond 2^32 / (D + 1) cells, some 50M samples, collect_skin instead.)
    const bool keys_fit = (D + 1) * result_.delaunay.cell_count <= UINT32_MAX;
    std::vector<Skin_facet> skin;
    if (keys_fit) skin.reserve((D == 3 ? 2 : 1) * std::size_t(sample_count_) + 64);  // closed
    const auto on_skin = [&](Cell_handle solid, Cell_handle outside) {
      if (!keys_fit) return;
      const int i = solid->index(outside);
      skin.push_back({static_cast<std::uint32_t>((D + 1) * std::size_t(solid->info()) + i),
                      facet_facing_out<Traits>(solid, i)});
    };
    const auto flood = [&](Cell_handle cell) {
      outside_[cell->info()] = 1;
      record_removal(cell, judged_reason(cell));
      stack.push_back(cell);
    };
    // The flood starts at the outer cells on the hull's skin (found from the cells outside the
    // hull, far fewer than the solid's), in the order the cells are numbered, and goes depth
    // first from each. Where it ends does not depend on the order: every outer cell the outside
    // reaches through outer cells (the order of the events does).
    std::vector<Cell_handle> starts;
    for (Cell_handle outside : outside_hull) {
      for (int i = 0; i <= D; ++i) {
        if (!is_outside(outside->neighbor(i))) starts.push_back(outside->neighbor(i));
      }
    }
    const auto by_number = [](Cell_handle a, Cell_handle b) { return a->info() < b->info(); };
    std::sort(starts.begin(), starts.end(), by_number);
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
    const double cells = static_cast<double>(result_.delaunay.cell_count);
    std::size_t reported = 0;
    for (Cell_handle start : starts) {
      if (is_outside(start) || !judged_outer(start)) continue;
      flood(start);
      while (!stack.empty()) {
        if (judge_.judged() >= reported + 262144) {
          reported = judge_.judged();
          report(double(reported) / cells);
        }
        const Cell_handle cell = stack.back();
        stack.pop_back();
        // The neighbours lie anywhere in memory: fetching them together, not one at a time.
        for (int i = 0; i <= D; ++i) prefetch(&*cell->neighbor(i));
        for (int i = 0; i <= D; ++i) {
          const Cell_handle neighbour = cell->neighbor(i);
          if (is_outside(neighbour)) continue;
          if (judged_outer(neighbour)) {
            flood(neighbour);
          } else {
            on_skin(neighbour, cell);
          }
        }
      }
    }
    std::vector<Cell_handle>().swap(starts);  // memory peaks in the skin check, below
    for (Cell_handle outside : outside_hull) {
      for (int i = 0; i <= D; ++i) {
        if (!is_outside(outside->neighbor(i))) on_skin(outside->neighbor(i), outside);
      }
    }
    std::vector<Cell_handle>().swap(outside_hull);
    if (flood_is_the_carving(pole_cells, keys_fit ? &skin : nullptr)) {
      result_.stats.carved_by_flood = true;
      return true;
    }
    // Undone: the hull again, as it was.
    removed_ = 0;
    result_.carving.events.clear();
    result_.surface.clear();
    start_from_hull();
    return false;
  }

  // The cheap test first, an outer cell left; then the skin, which is the result's surface if the
  // flood stands. (Its check, a closed 2-manifold through every sample, finds a sample the flood
  // left on no solid cell, or buried: on no skin facet either way.)
  //
  // Every solid cell on the skin was judged inner (the flood judged all it touched), so an outer
  // cell left lies in a pocket enclosed by the solid, judged or not. Pockets the carving keeps
  // change nothing; it opens one as a cavity only if it holds the outer poles of most of its
  // samples, so it is enough to judge the cells of the outer poles still in the solid. (Not
  // looking for the other pockets, the flood counts no outer cell kept.)
  // `skin` is the skin the flood collected (none: collect it now).
  // `pole_cells`: the outer poles' cells by number, in increasing order.
  bool flood_is_the_carving(const std::vector<int>& pole_cells, std::vector<Skin_facet>* skin) {
    // Most are outside now, or judged already; only the others are looked for, in a pass that
    // meets the cells in the order they are numbered (none, as a rule, where the flood stands).
    std::vector<int> unjudged;
    for (int number : pole_cells) {
      if (outside_[number]) continue;
      if (judge_.known(number)) {
        if (judge_.known_outer(number)) return false;
      } else {
        unjudged.push_back(number);
      }
    }
    std::size_t met = 0;
    for (auto cell : Traits::finite_cells(triangulation_)) {
      if (met == unjudged.size()) break;
      if (cell->info() != unjudged[met]) continue;
      ++met;
      if (judged_outer(cell)) return false;
    }
    result_.surface.clear();
    if (skin) {  // in collect_skin's order: by cell, then by facet
      std::sort(skin->begin(), skin->end(),
                [](const Skin_facet& a, const Skin_facet& b) { return a.key < b.key; });
      result_.surface.reserve(skin->size());
      for (const Skin_facet& facet : *skin) result_.surface.push_back(facet.sites);
      std::vector<Skin_facet>().swap(*skin);
    } else {
      sculpt::collect_skin<Traits>(
          triangulation_, [&](Cell_handle cell) { return !is_outside(cell); }, result_);
    }
    const Skin_check check = check_closed_skin<D>(sample_count_, result_.surface);
    // A piece of k samples, all on its skin, has at least k - D cells: one of more than
    // small_piece + D samples is no piece a group removal refuses to cut off, nor one that is
    // a part of its own.
    const bool stands =
        check.closed_manifold_through_all &&
        (check.pieces == 1 || check.smallest_piece > small_piece + D || small_pieces_are_parts());
    if (stands) checked_skin_ = check;
    return stands;
  }

  // Whether every piece of the surface with at most small_piece + D samples holds the inner
  // poles of most of its samples (piece_evidence.hpp), as the carving would let it be cut off.
  bool small_pieces_are_parts() const {
    Union_find pieces(static_cast<std::size_t>(sample_count_));
    for (const auto& facet : result_.surface) {
      for (int j = 1; j < D; ++j) pieces.unite(facet[0], facet[j]);
    }
    std::vector<std::vector<int>> members(static_cast<std::size_t>(sample_count_));
    for (int s = 0; s < sample_count_; ++s) members[pieces.find(s)].push_back(s);
    const auto in_solid = [&](std::size_t cell) { return outside_[cell] == 0; };
    for (const auto& samples : members) {
      if (!samples.empty() && samples.size() <= small_piece + D &&
          !holds_inner_poles_of_most(result_, samples, in_solid))
        return false;
    }
    return true;
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
      remove(opening, judged_reason(opening));
      for (int i = 0; i <= D; ++i) push_if_outer(opening->neighbor(i));
      carve_queue();
    }
  }

  // Sculpting by Boissonnat's condition never changes the topology of the solid: a torus stays
  // filled, its hole a wall of outer cells that cannot be removed one at a time. Each connected
  // group of outer cells still in the solid is tried as a whole: it goes if the surface stays a
  // manifold at every vertex of the group and no sample leaves the solid.
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
        opened = (!enclosed && try_remove_group(group)) || opened;
      }
      if (!opened) break;
    }
  }

  // A web of outer cells spanning a loop of the shape (between the strands of a knot) has no free
  // edge to carve from: its first removable cell is blocked by a vertex (or edge) already on the
  // surface on the web's other side. Removing that cell together with the outer cells around the
  // blocking vertex (edge) punches a hole through the web at once; it goes if the surface stays a
  // manifold there, and Boissonnat's carving then widens the hole.
  void punch_through() {
    std::vector<Cell_handle> group;
    for (int round = 0; round < 4; ++round) {
      bool punched = false;
      for (Cell_handle cell : std::vector<Cell_handle>(outer_cells_left())) {
        if (is_outside(cell)) continue;
        // Nothing changed around the cell (its faces, the cells at its vertices) and around the
        // vertex that failed since this punch last failed: it would fail again, the same way.
        const auto failed = failed_punches_.find(cell->info());
        if (failed != failed_punches_.end()) {
          bool unchanged = unchanged_since(failed->second.at, failed->second.tick);
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
        if (try_remove_group(group, &failed_at)) {
          punched = true;
        } else if (failed_at != Vertex_handle{}) {
          failed_punches_[cell->info()] = {tick_, failed_at};
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
  bool try_remove_group(const std::vector<Cell_handle>& group, Vertex_handle* failed_at = nullptr) {
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
    if (!fine) {
      for (Cell_handle cell : group) set_outside(cell, false);
      return false;
    }
    for (Cell_handle cell : group) record_removal(cell, judged_reason(cell));
    // Removing the group can make Boissonnat's condition hold for outer cells next to it.
    for (Cell_handle cell : group) {
      for (int i = 0; i <= D; ++i) push_if_outer(cell->neighbor(i));
    }
    carve_queue();
    return true;
  }

  bool buried(int sample) const {
    return solid_cells_at_[sample] > 0 && outside_cells_at_[sample] == 0;
  }

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
        float best_radius2 = -1;
        for (Cell_handle cell : star_) {
          if (triangulation_.is_infinite(cell) || is_outside(cell) || !can_remove(cell)) continue;
          const float r2 = radius2(cell);
          if (r2 > best_radius2) {
            best = cell;
            best_radius2 = r2;
          }
        }
        if (best_radius2 >= 0) {
          remove(best, Carve_reason::exposes_sample);
        } else if (!dig_to(v)) {
          still.push_back(v);
        }
      }
      if (still.size() == waiting.size()) break;
      waiting.swap(still);
    }
  }

  // A sample buried under the surface by more than one cell (under a nearly flat quad whose
  // other diagonal won, up to a spacing or so deep): no cell of its own touches the outside.
  // A short path of solid cells from the outside down to one of them, each removable when the
  // one before it is gone, is removed whole (each step a collapse, by Boissonnat's condition:
  // the topology stays, the surface dents down to the sample); a path that stops is put back.
  // Paths are searched breadth first from the sample's cells, at most dig_depth cells long.
  static constexpr int dig_depth = 6;
  bool dig_to(Vertex_handle v) {
    star_.clear();
    Traits::incident_cells(triangulation_, v, star_);
    // Breadth first through solid cells: each cell found, with the index of the one it was
    // reached from (-1: a cell of the sample).
    std::vector<std::pair<Cell_handle, int>> found;
    std::unordered_set<int> seen;
    for (Cell_handle cell : star_) {
      if (triangulation_.is_infinite(cell) || is_outside(cell)) continue;
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
          if (triangulation_.is_infinite(next) || is_outside(next)) continue;
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

  void record_what_stayed() {
    for (Cell_handle cell : outer_cells_left())
      result_.carving.kept_outer_cells.push_back(cell->info());
    for (int s = 0; s < sample_count_; ++s) {
      if (buried(s)) result_.carving.buried_samples.push_back(s);
    }
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
  std::vector<Cell_handle> star_, piece_, large_pieces_, own_parts_;
  std::vector<Vertex_handle> group_vertices_;
  // The change stamps (stamp_around), per site; empty in the flood, which needs none.
  std::vector<std::uint32_t> stamp_;
  std::uint32_t tick_ = 0;
  // Per outer cell whose punch failed at a vertex's test: the stamp then, and the vertex.
  struct Failed_punch {
    std::uint32_t tick;
    Vertex_handle at;
  };
  std::unordered_map<int, Failed_punch> failed_punches_;
  std::optional<Skin_check> checked_skin_;  // the flood's skin, when it passed the check
  std::vector<std::uint8_t> reached_;       // per cell: reached by a search of cuts_off_small_piece
  std::vector<std::array<int, 2>> link_;
  std::vector<std::pair<int, int>> link_ends_;
  std::vector<Cell_handle> outer_left_;  // judged outer and in the solid after the first carve
  std::vector<Cell_handle> stack_;
  std::vector<int> group_mark_;  // per cell: the outer group that last reached it
  int group_counter_ = 0;
};

}  // namespace sculpt
