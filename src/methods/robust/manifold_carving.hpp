// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 6b of the robust method: carve the hull of the samples from the outside in, one cell at
// a time, keeping the surface a 2-manifold (a closed curve in 2D) after every removal.
//
// The solid starts as every all-sample cell of DT(S ∪ BBV) (the hull of the samples); the
// outside is every other cell. Cells judged outer (cell_classification.hpp) are removed by
// Boissonnat's condition, largest circumball first (carved_solid.hpp); outer cells that never
// can be stay in the solid and are counted. Then the steps that change the solid's topology, by
// removing outer cells several at once (solid_openings.hpp): cavities, handles, punches through
// webs, a few rounds while they remove cells. Last, samples left buried inside the solid are
// brought onto the surface (buried_samples.hpp).
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
#include <climits>
#include <cstdint>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../../core/closed_skin_check.hpp"
#include "../../core/prefetch.hpp"
#include "../../core/solid_and_skin.hpp"
#include "../../core/union_find.hpp"
#include "cell_classification.hpp"
#include "piece_evidence.hpp"
#include "solid_openings.hpp"

namespace sculpt {

template <class Traits>
class Manifold_carving : public Solid_openings<Traits> {
  using Base = Solid_openings<Traits>;
  static constexpr int D = Traits::dimension;
  using Base::buried;
  using Base::carve_queue;
  using Base::expose_buried_samples;
  using Base::is_outside;
  using Base::is_sample;
  using Base::judge_;
  using Base::judged_outer;
  using Base::judged_reason;
  using Base::open_cavities;
  using Base::open_handles;
  using Base::outer_cells_left;
  using Base::outer_left_;
  using Base::outside_;
  using Base::punch_through;
  using Base::push_if_outer;
  using Base::queued_;
  using Base::record_removal;
  using Base::refused_punches_;
  using Base::removed_;
  using Base::report;
  using Base::result_;
  using Base::sample_count_;
  using Base::small_piece;
  using Base::stamp_;
  using Base::start_from_hull;
  using Base::triangulation_;
  using typename Base::Cell_handle;
  using typename Base::Vertex_handle;

 public:
  using Base::Base;
  using Base::removed;

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

  // The surface's check as a closed 2-manifold through every sample, when the flood stood (it
  // passed it): the topology follows from it without checking the surface again.
  std::optional<Skin_check> checked_skin() const {
    return result_.stats.carved_by_flood ? checked_skin_ : std::nullopt;
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
  // A facet of the skin: facet i of the solid cell numbered c, key (D + 1) c + i, its sites
  // facing out.
  struct Skin_facet {
    std::uint32_t key;
    Facet<D> sites;
  };

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

  void record_what_stayed() {
    for (Cell_handle cell : outer_cells_left())
      result_.carving.kept_outer_cells.push_back(cell->info());
    for (int s = 0; s < sample_count_; ++s) {
      if (buried(s)) result_.carving.buried_samples.push_back(s);
    }
    // The refused punches still in the solid, and the webs they stayed in: punches at cells
    // that share a sample are tries at one web (from its cells around one blocking vertex).
    std::vector<std::pair<int, Cell_handle>> refused;
    for (const auto& [number, cell] : refused_punches_) {
      if (!outside_[number]) refused.emplace_back(number, cell);
    }
    std::sort(refused.begin(), refused.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    Union_find webs(refused.size());
    std::unordered_map<int, std::size_t> first_with_sample;
    for (std::size_t i = 0; i < refused.size(); ++i) {
      result_.carving.refused_handles.push_back(refused[i].first);
      for (int k = 0; k <= D; ++k) {
        const auto [at, fresh] = first_with_sample.emplace(refused[i].second->vertex(k)->info(), i);
        if (!fresh) webs.unite(at->second, i);
      }
    }
    std::size_t count = 0;
    for (std::size_t i = 0; i < refused.size(); ++i) count += webs.find(i) == i;
    result_.stats.refused_handles = count;
  }

  std::optional<Skin_check> checked_skin_;  // the flood's skin, when it passed the check
};

}  // namespace sculpt
