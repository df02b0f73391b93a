// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a solid's skin (its oriented facets, solid_and_skin.hpp) is a closed 2-manifold (a set
// of closed curves in 2D) through every sample, and how its pieces are sized: the check the
// robust carving's flood must pass to stand for the carving (manifold_carving.hpp), and
// measure_topology's shortcut for such surfaces (facet_topology.cpp).
//
// A facet (a, b, c) facing out gives vertex a the directed link edge b -> c. The skin is a closed
// 2-manifold at a exactly when a's link edges make one directed cycle: every link vertex starts
// one edge and ends one, and walking from any edge comes back after visiting all. Then every
// edge ab lies on exactly two facets (b is in a's link once as a start and once as an end). In
// 2D an edge (a, b) leaves a and enters b: a closed curve enters and leaves each vertex once.
//
// One pass counts the facets at each vertex and one files them in compressed rows (4 bytes a
// facet and vertex: the check runs where memory peaks, in the carving); a vertex's link edges,
// a few (6 on average), are then sorted and walked in a small buffer.
// The pieces are the components of the facets' vertex graph (a union-find).
#pragma once

#include <algorithm>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "union_find.hpp"

namespace sculpt {

// With no samples and no facets, the empty skin passes, in 0 pieces.
struct Skin_check {
  bool closed_manifold_through_all = false;  // every sample on it, a 2-manifold at every one
  std::size_t pieces = 0;                    // connected components
  std::size_t smallest_piece = 0;            // samples on the smallest component
};

template <int D>
Skin_check check_closed_skin(std::size_t sample_count, const std::vector<Facet<D>>& facets) {
  Skin_check check;
  const int n = static_cast<int>(sample_count);
  for (const auto& facet : facets) {
    for (int j = 0; j < D; ++j) {
      if (facet[j] < 0 || facet[j] >= n) return check;  // a box corner on the skin
      for (int k = 0; k < j; ++k) {
        if (facet[k] == facet[j]) return check;  // a degenerate facet
      }
    }
  }
  if constexpr (D == 2) {
    std::vector<int> leaving(n, 0), entering(n, 0);
    for (const auto& edge : facets) {
      ++leaving[edge[0]];
      ++entering[edge[1]];
    }
    for (int s = 0; s < n; ++s) {
      if (leaving[s] != 1 || entering[s] != 1) return check;
    }
  } else {
    // The facets at each vertex, in compressed rows: the running sums of the counts end each
    // row, and filling a row from its end leaves its start there.
    std::vector<int> starts(n + 1, 0);
    for (const auto& facet : facets) {
      for (int v : facet) ++starts[v];
    }
    std::partial_sum(starts.begin(), starts.end(), starts.begin());
    std::vector<int> facets_at(starts[n]);
    for (std::size_t f = facets.size(); f-- > 0;) {
      for (int v : facets[f]) facets_at[--starts[v]] = static_cast<int>(f);
    }
    std::vector<std::pair<int, int>> link;
    for (int s = 0; s < n; ++s) {
      link.clear();
      for (int i = starts[s]; i < starts[s + 1]; ++i) {
        const auto& f = facets[facets_at[i]];
        const int at = f[0] == s ? 0 : f[1] == s ? 1 : 2;
        link.push_back({f[(at + 1) % 3], f[(at + 2) % 3]});
      }
      const auto first = link.begin(), last = link.end();
      const auto size = last - first;
      if (size < 3) return check;  // on no facet, or on too few to close around it
      std::sort(first, last);
      for (auto e = first + 1; e != last; ++e) {
        if (e->first == (e - 1)->first) return check;  // a link vertex starting two edges
      }
      // Walk the cycle from the first edge: each step finds the edge starting where the last
      // one ended; a missing one, or a return before every edge was walked, is no single cycle.
      int at = first->second;
      std::ptrdiff_t steps = 1;
      while (at != first->first) {
        const auto next = std::lower_bound(first, last, std::make_pair(at, -1));
        if (next == last || next->first != at || ++steps > size) return check;
        at = next->second;
      }
      if (steps != size) return check;
    }
  }
  // The pieces: the components of the facets' vertices.
  Union_find pieces(sample_count);
  for (const auto& facet : facets) {
    for (int j = 1; j < D; ++j) pieces.unite(facet[0], facet[j]);
  }
  std::vector<int> size(n, 0);
  for (int s = 0; s < n; ++s) ++size[pieces.find(s)];
  check.smallest_piece = sample_count;
  for (int s = 0; s < n; ++s) {
    if (size[s] == 0) continue;  // not a piece's root
    ++check.pieces;
    check.smallest_piece = std::min(check.smallest_piece, static_cast<std::size_t>(size[s]));
  }
  check.closed_manifold_through_all = true;
  return check;
}

// The topology statistics (as measure_topology fills them, facet_topology.hpp) of facets that
// passed check_closed_skin: no border, no non-manifold ridge or vertex, every sample used, and
// in 3D every edge on two facets, so E = 3F/2 and the Euler characteristic is V - F/2 (in 2D,
// V - E = 0). Spares measure_topology the sort of every ridge (about 1 s for the 2M triangles
// of a 1M torus).
template <int D>
void closed_skin_topology(std::size_t sample_count, std::size_t facet_count,
                          const Skin_check& check, Statistics& stats) {
  stats.facets = facet_count;
  stats.unused_samples = 0;
  stats.components = check.pieces;
  stats.boundary_ridges = stats.non_manifold_ridges = stats.non_manifold_vertices = 0;
  stats.boundary_loops = 0;
  const long vertices = static_cast<long>(sample_count), facets = static_cast<long>(facet_count);
  stats.euler_characteristic = D == 3 ? vertices - facets / 2 : vertices - facets;
}

}  // namespace sculpt
