// SPDX-License-Identifier: GPL-3.0-or-later
// Gaps in the sampling, filled: after the openings are taken out of a bordered surface and the
// rest is made a manifold (bordered_surface.hpp), a border loop can be a gap rather than an
// opening. Where the paper's candidates fold (slivers of nearly cospherical samples, as along the
// rulings of a regularly sampled cylinder), or noise stands a sliver on its edge, the extraction
// keeps neither fold and leaves a hole a few samples around amid the sheet (CGAL's
// cylinder_locally_refined: five loops of 3 to 7 samples; a sheet with noise of 2% of its
// spacing: nine). A loop whose fill covers no disc empty of samples wider than the test that took
// the openings out allows (core/spanning_openings.hpp, at the ratio the openings grow by) is no
// opening by that rule: it is filled, and the surface still interpolates.
//
//   for each border loop of at most 64 samples that is a simple cycle:
//     fill <- its least folded triangulation (least_folded_fill.hpp)
//     add fill if it folds by less than 135° and no triangle of it covers an opening
//
// An opening narrower than that test can tell was never found; filling its loop keeps the rule's
// word (CGAL's ChineseDragon: its two true holes are single missing triangles, closed either way).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "../../core/spanning_openings.hpp"
#include "../../core/union_find.hpp"
#include "../extraction/manifold_extraction.hpp"
#include "border_edges.hpp"
#include "least_folded_fill.hpp"

namespace sculpt {

// Loops longer than this are left as they are: the least folded fill costs the fourth power of
// the length (1.3M steps and 1.7 MB at 64), and a loop so long whose triangles all stay narrow is
// a slit along the sheet, not a gap.
inline constexpr int longest_gap_filled = 64;

// A border loop of an oriented surface: its vertices in the direction of the triangles' own
// edges (a -> b for a triangle (a, b, c) with (a, b) on the border), and for each edge
// vertices[i] -> vertices[i + 1] the third vertex of its triangle.
struct Border_loop {
  std::vector<int> vertices, apexes;
};

// The border loops that are simple cycles. Where one border edge arrives at a vertex and one
// leaves, the loop goes on along it. Where two fans of triangles meet at a vertex v (pinched:
// two border edges arrive and two leave), each gap between the fans is bounded by an edge
// arriving from one fan and one leaving the other, so a loop arriving from one fan leaves by the
// other's edge (noise leaves small holes side by side sharing a vertex: a noisy sheet at 5% of
// its spacing, a triangle hole and an 8-sample one sharing two); the fan's own leaving edge is
// found walking around v (fan_end, as pinched_vertices.hpp joins fans). A loop through a vertex
// where the border does not pair up so (more border edges, none leaving, a fan ending at neither
// leaving edge: turned against the others, or an edge on three triangles), or through one
// vertex twice, is left out; so are the loops through pinched vertices unless asked for.
enum class Pinches { left_out, passed };

inline std::vector<Border_loop> simple_border_loops(const std::vector<Facet<3>>& triangles,
                                                    const Edge_uses& uses,
                                                    Pinches pinches = Pinches::passed) {
  const std::vector<Border_edge> border = border_edges(triangles, uses);
  std::unordered_map<int, std::vector<int>> leaving, arriving;  // vertex -> border edges
  for (int e = 0; e < static_cast<int>(border.size()); ++e) {
    leaving[border[e].from].push_back(e);
    arriving[border[e].to].push_back(e);
  }
  std::unordered_set<int> pinched;  // two border edges arrive and two leave
  for (const auto& [v, edges] : leaving) {
    if (pinches == Pinches::passed && edges.size() == 2 && arriving[v].size() == 2) {
      pinched.insert(v);
    }
  }
  // The triangles at the pinched vertices, for walking around their fans.
  Third_vertex third;
  for (const auto& t : triangles) {
    if (pinched.empty()) break;
    if (!pinched.count(t[0]) && !pinched.count(t[1]) && !pinched.count(t[2])) continue;
    for (int j = 0; j < 3; ++j) third[directed_key(t[j], t[(j + 1) % 3])] = t[(j + 2) % 3];
  }
  // The border edge after e in its loop, or -1.
  const auto after = [&](int e) {
    const int v = border[e].to;
    const auto out = leaving.find(v);
    if (out == leaving.end()) return -1;
    const std::vector<int>& edges = out->second;
    if (edges.size() == 1 && arriving[v].size() == 1) return edges[0];
    if (!pinched.count(v)) return -1;
    // Not the edge leaving e's own fan: the other.
    const int own = fan_end(third, border[e].from, v, triangles.size());
    if (own == border[edges[0]].to) return edges[1];
    if (own == border[edges[1]].to) return edges[0];
    return -1;
  };
  std::vector<Border_loop> loops;
  std::vector<char> seen(border.size(), 0);
  // Started from each border edge in the triangles' order: the same loops in the same order, run
  // to run.
  for (int start = 0; start < static_cast<int>(border.size()); ++start) {
    if (seen[start]) continue;
    Border_loop loop;
    std::unordered_set<int> visited;
    bool simple = true;
    int e = start;
    do {
      seen[e] = 1;
      simple = simple && visited.insert(border[e].from).second;
      loop.vertices.push_back(border[e].from);
      loop.apexes.push_back(border[e].apex);
      e = after(e);
    } while (e >= 0 && e != start && !seen[e]);
    if (simple && e == start) loops.push_back(std::move(loop));
  }
  return loops;
}

inline std::vector<Border_loop> simple_border_loops(const std::vector<Facet<3>>& triangles,
                                                    Pinches pinches = Pinches::passed) {
  return simple_border_loops(triangles, edge_uses(triangles), pinches);
}

// A fill lies back over the surface rather than across a gap when two of its triangles, or one
// and the surface's triangle beside it, turn from each other by more than this: nearer folded
// flat back (180°, the outer border of a small sheet) than square (90°). Noise folds less: the
// missing triangles of a sheet with noise of 2% of its spacing turn by 95-115°; where thin parts
// of CGAL's ChineseDragon fold, some turn by 135-145° and stay open.
inline constexpr double sharpest_fill_fold_cos = -0.70710678118654752;  // cos 135°

// Why a loop gets the fill it gets.
enum class Loop_fill_verdict {
  gap,         // filled: a gap in the sampling
  opening,     // a triangle of its least folded fill covers a disc empty of samples
  torn,        // its least folded fill covers no empty disc but folds back: a hole noise tore
  unfillable,  // no fill: every triangulation needs an edge the surface has, or a triangle
               // beside the loop is degenerate
};

// The least folded triangulation of the loop (least_folded_fill.hpp), and whether it may go in:
// if it folds less than sharpest_fill_fold_cos and `not_to_add` allows each of its triangles.
// `not_to_add` judges the fill found, not the search: a search steered around it would look for
// the triangulation that slips a hole between the points it probes.
inline std::pair<Loop_fill_verdict, std::vector<Facet<3>>> fill_of_loop(
    const std::vector<Point<3>>& samples, const Border_loop& border, const Edge_uses& edges,
    const std::function<bool(const Facet<3>&)>& not_to_add) {
  const std::vector<int>& loop = border.vertices;
  std::vector<extraction_detail::Vector> normals;  // of the triangle on loop[i] -> loop[i + 1]
  for (std::size_t i = 0; i < loop.size(); ++i) {
    normals.push_back(extraction_detail::normal_of(samples, loop[i], loop[(i + 1) % loop.size()],
                                                   border.apexes[i]));
  }
  Loop_fill fill = least_folded_fill(samples, loop, normals, edges);
  if (fill.triangles.empty()) return {Loop_fill_verdict::unfillable, {}};
  for (const auto& triangle : fill.triangles) {
    if (not_to_add(triangle)) return {Loop_fill_verdict::opening, {}};
  }
  if (!(fill.sharpest_fold_cos > sharpest_fill_fold_cos)) return {Loop_fill_verdict::torn, {}};
  return {Loop_fill_verdict::gap, std::move(fill.triangles)};
}

// The pieces of the border of `surface` (its border edges joined at shared vertices, as
// Statistics::boundary_loops counts them) that are not openings: torn, every edge on a loop in
// `torn` (edge_key); short, not torn but through fewer samples than the rim of the smallest
// opening (smallest_opening_rim: a hole the bordered rule cut, not one the samples leave; small
// loops pinched together at a sample are one piece, counted by its samples, not its edges).
// `uses`: the surface's edge_uses.
struct Border_pieces_not_openings {
  std::size_t torn = 0, too_short = 0;
};

inline Border_pieces_not_openings count_pieces_not_openings(
    const std::vector<Facet<3>>& surface, const Edge_uses& uses,
    const std::unordered_set<std::uint64_t>& torn) {
  std::unordered_map<int, std::size_t> index;  // border vertex -> union-find element
  std::vector<std::pair<std::size_t, std::size_t>> border;
  std::vector<bool> on_torn_loop;
  for (const auto& [a, b, apex] : border_edges(surface, uses)) {
    const std::size_t i = index.emplace(a, index.size()).first->second;
    const std::size_t j = index.emplace(b, index.size()).first->second;
    border.push_back({i, j});
    on_torn_loop.push_back(torn.count(edge_key(a, b)) > 0);
  }
  Union_find pieces(index.size());
  for (const auto& [i, j] : border) pieces.unite(i, j);
  std::vector<char> all_torn(index.size(), 1);
  for (std::size_t e = 0; e < border.size(); ++e) {
    if (!on_torn_loop[e]) all_torn[pieces.find(border[e].first)] = 0;
  }
  std::vector<std::size_t> samples_on(index.size(), 0);
  for (std::size_t v = 0; v < index.size(); ++v) ++samples_on[pieces.find(v)];
  Border_pieces_not_openings count;
  for (std::size_t v = 0; v < index.size(); ++v) {
    if (pieces.find(v) != v) continue;
    if (all_torn[v]) {
      ++count.torn;
    } else if (samples_on[v] < smallest_opening_rim) {
      ++count.too_short;
    }
  }
  return count;
}

struct Gaps_filled {
  std::size_t filled = 0;       // loops filled
  std::size_t torn_loops = 0;   // border pieces left whose every loop is torn
  std::size_t short_loops = 0;  // the others through too few samples to be an opening's rim
};

// Fills the small border loops of `surface` that are gaps, and counts the border pieces left
// that are holes noise tore. With the loops through pinched vertices left out, the fans there
// can still be dropped (drop_pinched_fans) before their loops are filled.
inline Gaps_filled fill_gaps(const std::vector<Point<3>>& samples, std::vector<Facet<3>>& surface,
                             const std::function<bool(const Facet<3>&)>& not_to_add,
                             Pinches pinches = Pinches::passed) {
  Edge_uses edges = edge_uses(surface);
  Gaps_filled result;
  std::unordered_set<std::uint64_t> torn;
  for (const auto& loop : simple_border_loops(surface, edges, pinches)) {
    if (static_cast<int>(loop.vertices.size()) > longest_gap_filled) continue;
    const auto [verdict, fill] = fill_of_loop(samples, loop, edges, not_to_add);
    if (verdict == Loop_fill_verdict::torn) {
      const auto& v = loop.vertices;
      for (std::size_t i = 0; i < v.size(); ++i) torn.insert(edge_key(v[i], v[(i + 1) % v.size()]));
    }
    if (verdict != Loop_fill_verdict::gap) continue;
    for (const auto& t : fill) {
      surface.push_back(t);
      for (int j = 0; j < 3; ++j) ++edges[edge_key(t[j], t[(j + 1) % 3])];
    }
    ++result.filled;
  }
  const Border_pieces_not_openings not_openings = count_pieces_not_openings(surface, edges, torn);
  result.torn_loops = not_openings.torn;
  result.short_loops = not_openings.too_short;
  return result;
}

}  // namespace sculpt
