// SPDX-License-Identifier: GPL-3.0-or-later
#include "facet_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "closed_skin_check.hpp"
#include "union_find.hpp"

namespace sculpt {
namespace {

// A ridge is a facet less one vertex, its vertex indices sorted: an edge in 3D, a vertex in 2D.
// Ridges are packed in 64-bit keys (the smaller index in the high half), which sort several
// times faster than arrays of indices.
template <int D>
using Ridge = std::array<int, D - 1>;

template <int D>
std::uint64_t ridge_key(const Facet<D>& facet, int skip) {
  if constexpr (D == 2) {
    return static_cast<std::uint32_t>(facet[1 - skip]);
  } else {
    const auto a = static_cast<std::uint32_t>(facet[(skip + 1) % 3]);
    const auto b = static_cast<std::uint32_t>(facet[(skip + 2) % 3]);
    return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
  }
}

template <int D>
Ridge<D> ridge_of(std::uint64_t key) {
  if constexpr (D == 2) {
    return {static_cast<int>(key)};
  } else {
    return {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)};
  }
}

template <int D>
std::vector<std::uint64_t> ridges_of(const std::vector<Facet<D>>& facets) {
  std::vector<std::uint64_t> ridges;
  ridges.reserve(facets.size() * D);
  for (const auto& facet : facets) {
    for (int skip = 0; skip < D; ++skip) ridges.push_back(ridge_key<D>(facet, skip));
  }
  std::sort(ridges.begin(), ridges.end());
  return ridges;
}

// 3D: a vertex is manifold when the edges opposite it in its triangles (its link) are connected.
std::size_t count_non_manifold_vertices(std::size_t sample_count,
                                        const std::vector<Facet<3>>& triangles) {
  std::vector<std::size_t> offsets(sample_count + 1, 0);
  for (const auto& t : triangles) {
    for (int v : t) ++offsets[v + 1];
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::array<int, 2>> link(offsets.back());
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) link[fill[t[j]]++] = {t[(j + 1) % 3], t[(j + 2) % 3]};
  }
  std::size_t count = 0;
  std::vector<int> local;
  for (std::size_t v = 0; v < sample_count; ++v) {
    if (offsets[v] == offsets[v + 1]) continue;
    local.clear();
    for (auto e = offsets[v]; e < offsets[v + 1]; ++e) {
      local.push_back(link[e][0]);
      local.push_back(link[e][1]);
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    const auto index = [&](int x) {
      return static_cast<std::size_t>(std::lower_bound(local.begin(), local.end(), x) -
                                      local.begin());
    };
    Union_find pieces(local.size());
    std::size_t groups = local.size();
    for (auto e = offsets[v]; e < offsets[v + 1]; ++e) {
      const auto a = pieces.find(index(link[e][0])), b = pieces.find(index(link[e][1]));
      if (a != b) {
        pieces.unite(a, b);
        --groups;
      }
    }
    count += groups > 1;
  }
  return count;
}

}  // namespace

template <int D>
void measure_topology(std::size_t sample_count, const std::vector<Facet<D>>& facets,
                      Statistics& stats, const Skin_check* checked) {
  // A closed 2-manifold through every sample (the common result) has its topology follow from
  // a walk around each vertex, without sorting every ridge: 0.12 s -> 0.02 s on 300k triangles.
  // A method that checked its surface so already (the robust carving's flood) passes the check.
  const Skin_check closed = checked ? *checked : check_closed_skin<D>(sample_count, facets);
  if (closed.closed_manifold_through_all) {
    closed_skin_topology<D>(sample_count, facets.size(), closed, stats);
  } else {
    measure_topology_by_ridges<D>(sample_count, facets, stats);
  }
}

template <int D>
void measure_topology_by_ridges(std::size_t sample_count, const std::vector<Facet<D>>& facets,
                                Statistics& stats) {
  stats.facets = facets.size();

  std::vector<bool> used(sample_count, false);
  Union_find pieces(sample_count);
  for (const auto& facet : facets) {
    for (int v : facet) used[v] = true;
    for (int j = 1; j < D; ++j) pieces.unite(facet[0], facet[j]);
  }
  const auto used_count = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  stats.unused_samples = sample_count - used_count;
  stats.components = 0;
  for (std::size_t v = 0; v < sample_count; ++v) stats.components += used[v] && pieces.find(v) == v;

  // Ridges with their multiplicity: 1 = boundary, 2 = manifold, more = non-manifold.
  const auto ridges = ridges_of<D>(facets);
  std::size_t distinct = 0;
  stats.boundary_ridges = stats.non_manifold_ridges = 0;
  std::vector<Ridge<D>> boundary;
  for (std::size_t i = 0; i < ridges.size();) {
    std::size_t j = i;
    while (j < ridges.size() && ridges[j] == ridges[i]) ++j;
    ++distinct;
    if (j - i == 1) boundary.push_back(ridge_of<D>(ridges[i]));
    if (j - i > 2) ++stats.non_manifold_ridges;
    i = j;
  }
  stats.boundary_ridges = boundary.size();

  if constexpr (D == 3) {
    stats.euler_characteristic = static_cast<long>(used_count) - static_cast<long>(distinct) +
                                 static_cast<long>(facets.size());
    stats.non_manifold_vertices = count_non_manifold_vertices(sample_count, facets);
    // Boundary loops: connected pieces of the graph of border edges.
    Union_find loops(sample_count);
    std::vector<bool> on_border(sample_count, false);
    for (const auto& edge : boundary) {
      loops.unite(edge[0], edge[1]);
      on_border[edge[0]] = on_border[edge[1]] = true;
    }
    stats.boundary_loops = 0;
    for (std::size_t v = 0; v < sample_count; ++v) {
      stats.boundary_loops += on_border[v] && loops.find(v) == v;
    }
  } else {
    stats.euler_characteristic = static_cast<long>(used_count) - static_cast<long>(facets.size());
    stats.non_manifold_vertices = stats.non_manifold_ridges;
    // Open curves: components that have an end point.
    std::vector<bool> open(sample_count, false);
    for (const auto& end : boundary) open[pieces.find(end[0])] = true;
    stats.boundary_loops = static_cast<std::size_t>(std::count(open.begin(), open.end(), true));
  }
}

namespace {
template <int D>
Statistics topology_alone(std::size_t sample_count, const std::vector<Facet<D>>& facets) {
  Statistics stats;
  stats.dimension = D;
  stats.samples = sample_count;
  measure_topology<D>(sample_count, facets, stats);
  return stats;
}
}  // namespace

Statistics facet_topology(std::size_t sample_count, const std::vector<Facet<2>>& facets) {
  return topology_alone<2>(sample_count, facets);
}
Statistics facet_topology(std::size_t sample_count, const std::vector<Facet<3>>& facets) {
  return topology_alone<3>(sample_count, facets);
}

double triangles_reproduced(const std::vector<Facet<3>>& reference,
                            const std::vector<Facet<3>>& result) {
  if (reference.empty()) return 0;
  const auto sorted = [](Facet<3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<Facet<3>> have;
  have.reserve(result.size());
  for (const auto& t : result) have.push_back(sorted(t));
  std::sort(have.begin(), have.end());
  std::size_t found = 0;
  for (const auto& t : reference) found += std::binary_search(have.begin(), have.end(), sorted(t));
  return double(found) / double(reference.size());
}

template void measure_topology<2>(std::size_t, const std::vector<Facet<2>>&, Statistics&,
                                  const Skin_check*);
template void measure_topology<3>(std::size_t, const std::vector<Facet<3>>&, Statistics&,
                                  const Skin_check*);
template void measure_topology_by_ridges<2>(std::size_t, const std::vector<Facet<2>>&, Statistics&);
template void measure_topology_by_ridges<3>(std::size_t, const std::vector<Facet<3>>&, Statistics&);

}  // namespace sculpt
