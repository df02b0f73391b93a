// SPDX-License-Identifier: GPL-3.0-or-later
// The alpha CGAL's Alpha_shape_3::find_optimal_alpha(k) returns in REGULARIZED mode, found in one
// sweep over the cells instead of a binary search that walks the whole solid at every step.
//
// CGAL's rule: start from the smallest alpha at which every sample lies on a solid cell
// (find_alpha_solid), then binary-search the spectrum of alphas above it for the first whose
// solid (the finite cells of squared circumradius <= alpha) has at most k pieces joined through
// facets, treating that count as if it only fell as alpha grows. Each step counts the pieces with
// a traversal of every cell (bunny00: 18 traversals, half the method's time).
//
// Here the cells enter a union-find in order of alpha, once, and the count of pieces after each
// alpha of the spectrum is recorded; the same binary search then reads the counts. The probes and
// the answer are CGAL's, so the surface is the same.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "../../core/union_find.hpp"

namespace sculpt {

// `shape` is in REGULARIZED mode and its cells carry an int info, which this numbers. The
// index in the spectrum of the optimal alpha (none when CGAL's answer is past its end).
template <class Alpha_shape>
std::optional<std::size_t> optimal_alpha_index(const Alpha_shape& shape, std::size_t components) {
  using NT = typename Alpha_shape::NT;
  using Cell_handle = typename Alpha_shape::Cell_handle;
  const std::vector<NT> spectrum(shape.alpha_begin(), shape.alpha_end());
  std::vector<std::pair<NT, Cell_handle>> by_alpha;
  int count = 0;
  for (Cell_handle cell : shape.finite_cell_handles()) {
    cell->info() = count++;
    by_alpha.push_back({cell->get_alpha(), cell});
  }
  std::sort(by_alpha.begin(), by_alpha.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });

  // pieces_at[j]: how many pieces the solid at alpha spectrum[j] has.
  std::vector<std::size_t> pieces_at(spectrum.size());
  std::vector<char> solid(count, 0);
  Union_find pieces_of_cells(static_cast<std::size_t>(count));
  std::size_t pieces = 0, entered = 0;
  for (std::size_t j = 0; j < spectrum.size(); ++j) {
    for (; entered < by_alpha.size() && !(spectrum[j] < by_alpha[entered].first); ++entered) {
      const Cell_handle cell = by_alpha[entered].second;
      solid[cell->info()] = 1;
      ++pieces;
      for (int i = 0; i < 4; ++i) {
        const Cell_handle neighbour = cell->neighbor(i);
        if (shape.is_infinite(neighbour) || !solid[neighbour->info()]) continue;
        if (pieces_of_cells.unite(cell->info(), neighbour->info())) --pieces;
      }
    }
    pieces_at[j] = pieces;
  }
  // The pieces at any alpha: those at the largest alpha of the spectrum not above it.
  const auto pieces_at_alpha = [&](const NT& alpha) -> std::size_t {
    const auto after = std::upper_bound(spectrum.begin(), spectrum.end(), alpha);
    return after == spectrum.begin() ? 0 : pieces_at[after - spectrum.begin() - 1];
  };

  // CGAL's search, step for step.
  const NT alpha_solid = shape.find_alpha_solid();
  std::size_t first =
      std::lower_bound(spectrum.begin(), spectrum.end(), alpha_solid) - spectrum.begin();
  if (first == spectrum.size()) return std::nullopt;
  if (pieces_at_alpha(alpha_solid) == components) return first;
  std::ptrdiff_t length = static_cast<std::ptrdiff_t>(spectrum.size() - first) - 1;
  while (length > 0) {
    const std::ptrdiff_t half = length / 2;
    const std::size_t middle = first + static_cast<std::size_t>(half);
    if (pieces_at[middle] > components) {
      first = middle + 1;
      length = length - half - 1;
    } else {
      length = half;
    }
  }
  if (pieces_at[first] > components) ++first;
  if (first >= spectrum.size()) return std::nullopt;
  return first;
}

}  // namespace sculpt
