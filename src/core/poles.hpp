// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 2: Amenta's poles. The Voronoi cell of a sample s is bounded (thanks to the box), and its
// vertices are the circumcentres of the Delaunay cells incident to s, each at distance equal to
// that cell's circumradius. So
//   p+ = circumcentre of the incident cell with the largest circumradius,
//   p- = circumcentre of the incident cell with the largest circumradius among those on the
//        other side of s: (c - s) · (p+ - s) < 0.
// Among equal radii the cell met first in the triangulation's order of finite cells wins.
// A pole is a Delaunay cell; one cell can be a pole of several samples, so poles are deduplicated
// and their pairing (the two poles of each sample) is stored as a graph.
#pragma once

#include <CGAL/squared_distance_2.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "prefetch.hpp"
#include "stage_clock.hpp"

namespace sculpt {

template <class Traits>
void find_poles(const typename Traits::Triangulation& triangulation,
                Reconstruction<Traits::dimension>& result, const Stage_clock& clock) {
  constexpr int D = Traits::dimension;
  using Cell_handle = typename Traits::Cell_handle;
  using Cgal_point = typename Traits::Cgal_point;
  const int n = static_cast<int>(result.sites.size()) - (1 << D);
  const auto squared_radius = [&](Cell_handle cell, const Cgal_point& center) {
    return CGAL::squared_distance(center, cell->vertex(0)->point());
  };

  // Circumcentres are computed again in each pass rather than stored: storing them for every cell
  // would take 24 bytes a cell (475 MB for the 19.8M cells of a 1M-point torus) to save ~2 s.
  // Keeping a few largest balls per sample in one pass does not find p- either: a sample's
  // largest Voronoi vertices crowd together at the far end of its cell, on the side of p+
  // (measured: the 4 largest are all on that side for 98% of bunny00's samples).
  // What a pole needs of its cell (centre, radius, sites) is kept per sample as the passes find
  // it, so that no cell is visited again out of the container's order (each such visit a cache
  // miss). The radii and centres, read for every cell at each of its samples, are kept apart from
  // the rest, written only when a larger ball is found (a few times a sample): compact arrays
  // that stay in cache. Bunny00 subdivided (150k): the stage 0.23 -> 0.17 s.
  struct Pole_cell {
    int cell = -1;  // index among the finite cells
    Cell<D> sites{};
  };
  const auto keep = [](Pole_cell& pole_cell, Cell_handle cell) {
    pole_cell.cell = cell->info();
    for (int i = 0; i <= D; ++i) pole_cell.sites[i] = cell->vertex(i)->info();
  };

  // Every finite cell with its circumball, in the container's order, for `visit`. The samples'
  // entries a pass reads (`per_sample`) lie anywhere in memory (in the input's order), so each
  // cell is visited two cells after it is met: its vertices are asked for when it is met, its
  // samples' entries one cell later, while the cell before is visited (300k random torus: the
  // stage 0.73 -> 0.63 s).
  const auto finite = Traits::finite_cells(triangulation);
  const double cells = 2.0 * static_cast<double>(result.delaunay.cell_count);
  std::size_t done = 0;
  const auto for_each_ball = [&](auto&& visit, const auto&... per_sample) {
    const auto ball = [&](Cell_handle cell) {
      if (++done % 262144 == 0) clock.report(double(done) / cells);
      const Cgal_point center = Traits::circumcenter(triangulation, cell);
      visit(cell, center, squared_radius(cell, center));
    };
    Cell_handle previous, before_previous;  // met one and two cells ago
    std::size_t met = 0;
    for (const Cell_handle cell : finite) {
      for (int i = 0; i <= D; ++i) prefetch(&*cell->vertex(i));
      if (met >= 1) {
        for (int i = 0; i <= D; ++i) {
          const int s = previous->vertex(i)->info();
          if (s < n) (prefetch(&per_sample[s]), ...);
        }
      }
      if (met >= 2) ball(before_previous);
      before_previous = previous;
      previous = cell;
      ++met;
    }
    if (met >= 2) ball(before_previous);
    if (met >= 1) ball(previous);
  };

  // Pass 1: p+ of every sample.
  std::vector<double> plus_radius2(n, -1.0);  // -1: none found (yet)
  std::vector<Cgal_point> plus_center(n);
  std::vector<Pole_cell> plus(n);
  for_each_ball(
      [&](Cell_handle cell, const Cgal_point& center, double r2) {
        for (int i = 0; i <= D; ++i) {
          const int s = cell->vertex(i)->info();
          if (s < n && r2 > plus_radius2[s]) {
            plus_radius2[s] = r2;
            plus_center[s] = center;
            keep(plus[s], cell);
          }
        }
      },
      plus_radius2);

  // Pass 2: p- of every sample.
  std::vector<double> minus_radius2(n, -1.0);
  std::vector<Cgal_point> minus_center(n);
  std::vector<Pole_cell> minus(n);
  for_each_ball(
      [&](Cell_handle cell, const Cgal_point& center, double r2) {
        for (int i = 0; i <= D; ++i) {
          const int s = cell->vertex(i)->info();
          if (s >= n || r2 <= minus_radius2[s]) continue;
          const auto& sample = cell->vertex(i)->point();
          if ((center - sample) * (plus_center[s] - sample) < 0) {
            minus_radius2[s] = r2;
            minus_center[s] = center;
            keep(minus[s], cell);
          }
        }
      },
      minus_radius2, plus_center);

  // Deduplicate: one pole per Delaunay cell, numbered in the order the samples first name them
  // (sample by sample, p+ before p-). Sorting the 2n namings by cell finds the repeats without a
  // table over all cells (80 MB for the 19.8M cells of a 1M-point torus).
  auto& stage = result.poles;
  struct Naming {
    int cell;  // index among the finite cells
    int slot;  // 2 s for the p+ of sample s, 2 s + 1 for its p-
  };
  std::vector<Naming> namings;
  namings.reserve(2 * static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    namings.push_back({plus[s].cell, 2 * s});
    if (minus_radius2[s] >= 0) namings.push_back({minus[s].cell, 2 * s + 1});
  }
  std::sort(namings.begin(), namings.end(), [](const Naming& a, const Naming& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.slot < b.slot;
  });
  // The first naming of each cell, in naming order, gives the poles their numbers.
  std::vector<int> first_slots;
  for (std::size_t i = 0; i < namings.size(); ++i) {
    if (i == 0 || namings[i].cell != namings[i - 1].cell) first_slots.push_back(namings[i].slot);
  }
  std::sort(first_slots.begin(), first_slots.end());
  stage.poles.resize(first_slots.size());
  std::vector<int> pole_of_slot(2 * static_cast<std::size_t>(n), -1);
  for (std::size_t pole = 0; pole < first_slots.size(); ++pole) {
    const int slot = first_slots[pole];
    pole_of_slot[slot] = static_cast<int>(pole);
    const Pole_cell& pole_cell = slot % 2 == 0 ? plus[slot / 2] : minus[slot / 2];
    Pole<D>& p = stage.poles[pole];
    p.center = Traits::from_cgal(slot % 2 == 0 ? plus_center[slot / 2] : minus_center[slot / 2]);
    p.radius = std::sqrt(slot % 2 == 0 ? plus_radius2[slot / 2] : minus_radius2[slot / 2]);
    p.cell = static_cast<std::size_t>(pole_cell.cell);
    p.sites = pole_cell.sites;
    for (int i = 0; i <= D; ++i) p.convex = p.convex || p.sites[i] >= n;
  }
  stage.positive_pole.assign(n, -1);
  stage.negative_pole.assign(n, -1);
  for (std::size_t i = 0; i < namings.size();) {
    std::size_t j = i;
    while (j < namings.size() && namings[j].cell == namings[i].cell) ++j;
    // namings[i] is this cell's first naming: its pole's number is its rank among first namings.
    const int pole = pole_of_slot[namings[i].slot];
    for (std::size_t k = i; k < j; ++k) {
      const int slot = namings[k].slot;
      (slot % 2 == 0 ? stage.positive_pole : stage.negative_pole)[slot / 2] = pole;
    }
    i = j;
  }

  // The pairing graph in compressed rows: partners of each pole, sorted, without repeats.
  const int pole_count = static_cast<int>(stage.poles.size());
  auto& offsets = stage.partner_offsets;
  offsets.assign(pole_count + 1, 0);
  for (int s = 0; s < n; ++s) {
    if (stage.negative_pole[s] < 0) continue;
    ++offsets[stage.positive_pole[s] + 1];
    ++offsets[stage.negative_pole[s] + 1];
  }
  for (int p = 0; p < pole_count; ++p) offsets[p + 1] += offsets[p];
  std::vector<int> partners(offsets.back());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (int s = 0; s < n; ++s) {
    const int a = stage.positive_pole[s], b = stage.negative_pole[s];
    if (b < 0) continue;
    partners[fill[a]++] = b;
    partners[fill[b]++] = a;
  }
  stage.partners.clear();
  stage.partners.reserve(partners.size());
  for (int p = 0; p < pole_count; ++p) {
    const auto first = partners.begin() + offsets[p], last = partners.begin() + offsets[p + 1];
    std::sort(first, last);
    offsets[p] = static_cast<int>(stage.partners.size());  // rows only shrink: safe in place
    stage.partners.insert(stage.partners.end(), first, std::unique(first, last));
  }
  offsets[pole_count] = static_cast<int>(stage.partners.size());
}

}  // namespace sculpt
