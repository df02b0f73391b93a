// SPDX-License-Identifier: GPL-3.0-or-later
// Samples left off a bordered surface, attached to its border, and the border's sharp notches
// closed. Where the paper's candidates fold along a border (the corners of a sheet, a patch of
// a flat face at its edge), the extraction can keep border edges that pass by samples belonging
// beyond them, and those samples are left off: the surface no longer interpolates them. A front
// advances from the border over them, as an advancing front does, one layer a round:
//
//   repeat while some sample was attached:
//     for each sample s on no triangle, the narrowest triangle (b, a, s) on a border edge
//       (a, b) at s's nearest border vertices that may be added (not wider than 2 spacings:
//       core/spanning_openings.hpp; turned less than 60 degrees from the triangle on (a, b))
//     add (b, a, s) where s and (a, b) choose each other (s is the narrowest for the edge too:
//       near samples go first, far ones do not reach over them), one at a border vertex
//       a round (two on neighbouring edges could overlap)
//   then, where the border runs u -> v -> w at an angle under 60 degrees at v (the spikes the
//   front leaves), add (w, v, u) when it may be added and u-w is no edge yet
//
// The border loop a -> b becomes a -> s -> b, and u -> v -> w becomes u -> w: the surface
// stays a manifold with the same loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sculpt/sculpt.hpp>
#include <unordered_map>
#include <vector>

#include "../../core/point_tree.hpp"
#include "../../core/spanning_openings.hpp"
#include "../extraction/manifold_extraction.hpp"
#include "border_edges.hpp"

namespace sculpt {

// How many of the nearest border vertices offer their border edges to a left-off sample.
inline constexpr int border_vertices_asked = 8;
// A triangle attached turns at most this much from the one it leans on (a flap standing up from
// the sheet puts an outlier on the surface, not a sample of it).
inline constexpr double steepest_attachment = 60.0 * M_PI / 180;

// Attaches the samples on no triangle of `surface` to its border where they fit; returns how many.
inline std::size_t attach_left_off_samples(const std::vector<Point<3>>& samples,
                                           std::vector<Facet<3>>& surface,
                                           const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::dot;
  using extraction_detail::normal_of;
  std::vector<char> on_surface(samples.size(), 0);
  for (const auto& t : surface) {
    for (int v : t) on_surface[v] = 1;
  }
  std::vector<int> left_off;
  for (int s = 0; s < static_cast<int>(samples.size()); ++s) {
    if (!on_surface[s]) left_off.push_back(s);
  }
  if (left_off.empty()) return 0;
  // The border, kept up to date as triangles are added: each directed edge a -> b of a triangle
  // (a, b, c) whose edge is on no other, with its c.
  std::unordered_map<std::uint64_t, int> apex_of;  // directed (a << 32 | b) -> c
  for (const auto& [a, b, c] : border_edges(surface, edge_uses(surface))) {
    apex_of[directed_key(a, b)] = c;
  }
  const double cos_steepest = std::cos(steepest_attachment);
  std::size_t attached = 0;
  for (bool progress = true; progress && !left_off.empty();) {
    progress = false;
    std::vector<std::uint64_t> edge_list;  // the border's directed keys, sorted
    for (const auto& [key, apex] : apex_of) edge_list.push_back(key);
    if (edge_list.empty()) break;
    std::sort(edge_list.begin(), edge_list.end());
    std::unordered_map<int, std::vector<int>> border_edges_at;  // vertex -> its edges' indices
    std::vector<int> border_vertices;
    std::vector<Point<3>> border_points;
    for (int index = 0; index < static_cast<int>(edge_list.size()); ++index) {
      for (int v : {static_cast<int>(edge_list[index] >> 32),
                    static_cast<int>(edge_list[index] & 0xffffffffu)}) {
        auto& at = border_edges_at[v];
        if (at.empty()) {
          border_vertices.push_back(v);
          border_points.push_back(samples[v]);
        }
        at.push_back(index);
      }
    }
    const Point_tree<3> tree(border_points.data(), border_points.data() + border_points.size());
    // Each left-off sample's narrowest fitting triangle on a border edge; each border edge's
    // narrowest over all the samples it fits. A sample goes on its edge when they choose each
    // other: the front then advances by one layer a round, nearest samples first, instead of
    // far samples reaching over near ones.
    std::vector<int> chosen_edge(left_off.size(), -1);
    std::vector<double> chosen_radius(left_off.size(), INFINITY);
    std::vector<double> narrowest_at_edge(edge_list.size(), INFINITY);
    for (std::size_t i = 0; i < left_off.size(); ++i) {
      const int s = left_off[i];
      for (int near : tree.k_nearest_to(samples[s], border_vertices_asked)) {
        for (int e : border_edges_at[border_vertices[near]]) {
          const std::uint64_t key = edge_list[e];
          const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
          const int c = apex_of[key];
          const Facet<3> added = {b, a, s};
          const double radius = facet_circumradius<3>(samples, added);
          if (!(radius < chosen_radius[i]) && !(radius < narrowest_at_edge[e])) continue;
          // The triangle leaned on, (a, b, c), and the one added, (b, a, s): the turn between
          // their normals.
          const auto leaned = normal_of(samples, a, b, c), normal = normal_of(samples, b, a, s);
          const double lengths = std::sqrt(dot(leaned, leaned) * dot(normal, normal));
          if (!(dot(leaned, normal) > cos_steepest * lengths) || not_to_add(added)) continue;
          narrowest_at_edge[e] = std::min(narrowest_at_edge[e], radius);
          if (radius < chosen_radius[i]) chosen_edge[i] = e, chosen_radius[i] = radius;
        }
      }
    }
    // One triangle a round at a border vertex: two added on neighbouring edges could overlap.
    std::vector<char> touched(samples.size(), 0);
    std::vector<int> still_left_off;
    for (std::size_t i = 0; i < left_off.size(); ++i) {
      const int e = chosen_edge[i], s = left_off[i];
      const std::uint64_t key = e < 0 ? 0 : edge_list[e];
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      if (e < 0 || chosen_radius[i] > narrowest_at_edge[e] || touched[a] || touched[b]) {
        still_left_off.push_back(s);
        continue;
      }
      touched[a] = touched[b] = 1;
      surface.push_back({b, a, s});
      apex_of.erase(key);
      apex_of[directed_key(a, s)] = b;
      apex_of[directed_key(s, b)] = a;
      ++attached;
      progress = true;
    }
    left_off = std::move(still_left_off);
  }
  return attached;
}

// The largest angle at a border vertex, between its two border edges, that is a notch to close.
inline constexpr double sharpest_notch_kept = 60.0 * M_PI / 180;

// Closes the sharp notches of the border: where the border runs u -> v -> w with an angle at v
// under 60 degrees, the triangle (w, v, u) is added when it may be added (not_to_add), turns
// less than 90 degrees from both triangles it leans on and u-w is no edge yet; repeated until
// none is left. Returns how many were closed.
inline std::size_t close_border_notches(const std::vector<Point<3>>& samples,
                                        std::vector<Facet<3>>& surface,
                                        const std::function<bool(const Facet<3>&)>& not_to_add) {
  using extraction_detail::dot;
  using extraction_detail::minus;
  std::size_t closed = 0;
  for (bool progress = true; progress;) {
    progress = false;
    const Edge_uses uses = edge_uses(surface);
    // Per border vertex: the border edge arriving and the one leaving, with their triangles'
    // third vertices; -1 where there is none, -2 where there are several.
    struct Ends {
      int from = -1, from_apex = -1, to = -1, to_apex = -1;
    };
    std::unordered_map<int, Ends> ends;
    for (const auto& [a, b, c] : border_edges(surface, uses)) {
      Ends& at_a = ends[a];
      at_a.to = at_a.to == -1 ? b : -2;
      at_a.to_apex = c;
      Ends& at_b = ends[b];
      at_b.from = at_b.from == -1 ? a : -2;
      at_b.from_apex = c;
    }
    std::vector<int> border(ends.size());
    std::transform(ends.begin(), ends.end(), border.begin(), [](const auto& e) { return e.first; });
    std::sort(border.begin(), border.end());
    std::vector<char> touched(samples.size(), 0);
    for (int v : border) {
      const Ends& e = ends[v];
      const int u = e.from, w = e.to;
      if (u < 0 || w < 0 || u == w || touched[u] || touched[v] || touched[w]) continue;
      const auto to_u = minus(samples[u], samples[v]), to_w = minus(samples[w], samples[v]);
      const double lengths = std::sqrt(dot(to_u, to_u) * dot(to_w, to_w));
      if (lengths == 0 || dot(to_u, to_w) <= std::cos(sharpest_notch_kept) * lengths) continue;
      if (uses.count(edge_key(u, w))) continue;
      const Facet<3> added = {w, v, u};
      if (!closes_corner_facing_on(samples, u, v, w, e.from_apex, e.to_apex) || not_to_add(added))
        continue;
      surface.push_back(added);
      touched[u] = touched[v] = touched[w] = 1;
      ++closed;
      progress = true;
    }
  }
  return closed;
}

}  // namespace sculpt
