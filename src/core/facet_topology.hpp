// SPDX-License-Identifier: GPL-3.0-or-later
// Topology of a reconstruction's facets (triangles in 3D, edges in 2D), as reported in the
// statistics and checked by the tests: boundary and non-manifold ridges, boundary loops,
// connected components, Euler characteristic and unused samples.
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

struct Skin_check;

// Fills the topology fields of `stats` (boundary_ridges ... unused_samples, facets). `checked`,
// when given, is the facets' check_closed_skin, already made.
template <int D>
void measure_topology(std::size_t sample_count, const std::vector<Facet<D>>& facets,
                      Statistics& stats, const Skin_check* checked = nullptr);

// The same, always by counting every ridge (measure_topology takes a shortcut for closed
// 2-manifolds through every sample; the tests hold the two to the same numbers).
template <int D>
void measure_topology_by_ridges(std::size_t sample_count, const std::vector<Facet<D>>& facets,
                                Statistics& stats);

}  // namespace sculpt
