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
#include "../extraction/manifold_extraction.hpp"
#include "border_edges.hpp"
#include "least_folded_fill.hpp"

namespace sculpt {

// Loops longer than this are left as they are: the least folded fill costs the fourth power of
// the length (1.3M steps and 10 MB at 64), and a loop so long whose triangles all stay narrow is
// a slit along the sheet, not a gap.
inline constexpr int longest_gap_filled = 64;

// A border loop of an oriented surface: its vertices in the direction of the triangles' own
// edges (a -> b for a triangle (a, b, c) with (a, b) on the border), and for each edge
// vertices[i] -> vertices[i + 1] the third vertex of its triangle.
struct Border_loop {
  std::vector<int> vertices, apexes;
};

// The border loops that are simple cycles: a loop through a vertex where more or fewer than one
// border edge arrives or leaves is left out.
inline std::vector<Border_loop> simple_border_loops(const std::vector<Facet<3>>& triangles,
                                                    const Edge_uses& uses) {
  std::unordered_map<int, std::pair<int, int>> next;  // vertex -> (next vertex, apex)
  std::unordered_map<int, int> arriving;
  std::unordered_set<int> branching;
  for (const auto& [a, b, apex] : border_edges(triangles, uses)) {
    if (!next.emplace(a, std::make_pair(b, apex)).second) branching.insert(a);
    if (++arriving[b] > 1) branching.insert(b);
  }
  std::vector<int> starts;
  for (const auto& [v, unused] : next) starts.push_back(v);
  std::sort(starts.begin(), starts.end());  // the same loops in the same order, run to run
  std::vector<Border_loop> loops;
  std::unordered_set<int> seen;
  for (int start : starts) {
    if (seen.count(start)) continue;
    Border_loop loop;
    bool simple = true;
    int v = start;
    do {
      seen.insert(v);
      simple = simple && !branching.count(v) && arriving.count(v);
      const auto found = next.find(v);
      if (found == next.end()) {
        simple = false;
        break;
      }
      loop.vertices.push_back(v);
      loop.apexes.push_back(found->second.second);
      v = found->second.first;
    } while (v != start && !seen.count(v));
    if (simple && v == start) loops.push_back(std::move(loop));
  }
  return loops;
}

inline std::vector<Border_loop> simple_border_loops(const std::vector<Facet<3>>& triangles) {
  return simple_border_loops(triangles, edge_uses(triangles));
}

// A fill lies back over the surface rather than across a gap when two of its triangles, or one
// and the surface's triangle beside it, turn from each other by more than this: nearer folded
// flat back (180°, the outer border of a small sheet) than square (90°). Noise folds less: the
// missing triangles of a sheet with noise of 2% of its spacing, and of CGAL's ChineseDragon where
// thin parts fold, turn by 90-145°.
inline constexpr double sharpest_fill_fold_cos = -0.7071;  // 135°

// The least folded triangulation of the loop (least_folded_fill.hpp), if it folds less than
// sharpest_fill_fold_cos and `not_to_add` allows each of its triangles; empty otherwise.
inline std::vector<Facet<3>> fill_of_loop(const std::vector<Point<3>>& samples,
                                          const Border_loop& border, const Edge_uses& edges,
                                          const std::function<bool(const Facet<3>&)>& not_to_add) {
  const std::vector<int>& loop = border.vertices;
  std::vector<extraction_detail::Vector> normals;  // of the triangle on loop[i] -> loop[i + 1]
  for (std::size_t i = 0; i < loop.size(); ++i) {
    normals.push_back(extraction_detail::normal_of(samples, loop[i], loop[(i + 1) % loop.size()],
                                                   border.apexes[i]));
  }
  Loop_fill fill = least_folded_fill(samples, loop, normals, edges);
  if (fill.triangles.empty() || !(fill.sharpest_fold_cos > sharpest_fill_fold_cos)) return {};
  for (const auto& triangle : fill.triangles) {
    if (not_to_add(triangle)) return {};
  }
  return std::move(fill.triangles);
}

// Fills the small border loops of `surface` that are gaps; returns how many.
inline std::size_t fill_gaps(const std::vector<Point<3>>& samples, std::vector<Facet<3>>& surface,
                             const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::edge_key;
  Edge_uses edges = edge_uses(surface);
  std::size_t filled = 0;
  for (const auto& loop : simple_border_loops(surface, edges)) {
    if (static_cast<int>(loop.vertices.size()) > longest_gap_filled) continue;
    const std::vector<Facet<3>> fill = fill_of_loop(samples, loop, edges, not_to_add);
    if (fill.empty()) continue;
    for (const auto& t : fill) {
      surface.push_back(t);
      for (int j = 0; j < 3; ++j) ++edges[edge_key(t[j], t[(j + 1) % 3])];
    }
    ++filled;
  }
  return filled;
}

}  // namespace sculpt
