// Gaps in the sampling, filled: after the openings are taken out of a bordered surface and the
// rest is made a manifold (bordered_surface.hpp), a border loop can be a gap rather than an
// opening. Where the paper's candidates fold (slivers of nearly cospherical samples, as along the
// rulings of a regularly sampled cylinder), the extraction keeps neither fold and leaves a hole a
// few samples around amid the sheet (CGAL's cylinder_locally_refined: five loops of 3 to 7
// samples). A loop that can be triangulated with no triangle wider than the test that took the
// openings out allows (core/spanning_openings.hpp, at the ratio the openings grow by) is no
// opening by that rule: it is filled with that triangulation, and the surface still interpolates.
//
//   for each border loop of at most 64 samples that is a simple cycle:
//     fill <- ear clipping, each time the ear with the smallest circumradius among those that
//             continue the surface (no fold back over it, no edge it has already)
//     add fill if every ear could be clipped and none is too wide
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

namespace sculpt {

// Loops longer than this are left as they are: ear clipping costs the square of the length, and a
// loop so long whose triangles all stay narrow is a slit along the sheet, not a gap.
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

// A triangulation of the loop by ear clipping, each time the ear with the smallest circumradius
// among those that continue the surface: facing against the loop's edges, turned less than 90
// degrees from the triangles on the edges they cover (an ear at a reflex corner, or across the
// outer border of a sheet, lies back over the surface and fails this), and whose new edge is not
// an edge of the surface already. Empty when no ear is left or the one taken may not be added.
inline std::vector<Facet<3>> fill_of_loop(const std::vector<Point<3>>& samples,
                                          const Border_loop& border, const Edge_uses& edges,
                                          const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::dot;
  using extraction_detail::edge_key;
  using extraction_detail::normal_of;
  using extraction_detail::Vector;
  std::vector<int> loop = border.vertices;
  // normals[i]: of the triangle on the loop's edge loop[i] -> loop[i + 1].
  std::vector<Vector> normals;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    normals.push_back(normal_of(samples, loop[i], loop[(i + 1) % loop.size()], border.apexes[i]));
  }
  std::vector<Facet<3>> fill;
  while (loop.size() >= 3) {
    const int k = static_cast<int>(loop.size());
    int best = -1;
    double best_radius = INFINITY;
    for (int i = 0; i < k; ++i) {
      const int before = loop[(i + k - 1) % k], after = loop[(i + 1) % k];
      if (k > 3 && edges.count(edge_key(before, after))) continue;
      const Vector normal = normal_of(samples, after, loop[i], before);
      // The last ear (k = 3) covers a third edge, not looked at: a missing triangle where a thin
      // part folds sharply is still filled (checking it refused 42 of ChineseDragon's fills).
      if (dot(normal, normals[i]) <= 0 || dot(normal, normals[(i + k - 1) % k]) <= 0) continue;
      const double radius = facet_circumradius<3>(samples, {after, loop[i], before});
      if (best < 0 || radius < best_radius) best = i, best_radius = radius;
    }
    if (best < 0) return {};
    const Facet<3> ear = {loop[(best + 1) % k], loop[best], loop[(best + k - 1) % k]};
    if (not_to_add(ear)) return {};
    fill.push_back(ear);
    // The ear's edge before -> after is the loop's edge now.
    normals[(best + k - 1) % k] = normal_of(samples, ear[0], ear[1], ear[2]);
    normals.erase(normals.begin() + best);
    loop.erase(loop.begin() + best);
  }
  return fill;
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
