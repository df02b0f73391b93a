// SPDX-License-Identifier: GPL-3.0-or-later
// The tight co-cone of Dey and Goswami (2003), a watertight surface from the co-cone's:
//   S0 <- the co-cone's surface (cocone_method.hpp: undersampling, candidates, extraction)
//   good <- the samples whose triangles in S0 make one closed fan around them (an umbrella)
//   outside <- the cells of DT touching a box corner
//   peel: from an outside cell c across a facet f not in S0 to its neighbour d when
//       a good sample of d lies on f (the walk turns about that sample, and its umbrella
//           stops it: the cells on the far side stay in), or
//       every vertex of d is bad, and f is not d's smallest facet (a cell among bad samples
//           is peeled, but not through its smallest facet, the one most likely on the surface)
//   a good sample that no outside cell reached is bad after all; peel again
//   solid <- the cells not peeled; surface <- its skin
// The surface is the boundary of a set of cells, so it has no hole; where the co-cone had one
// (undersampled, or pruned away), the cells there decide. It can have non-manifold edges or
// vertices, which the verdict counts. The rules are those of the authors' program (Goswami's
// TightCocone): the paper's "marking" of the cells around good samples and its "peeling" are
// the two kinds of step of this one walk.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <deque>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/solid_and_skin.hpp"
#include "../../core/stage_clock.hpp"
#include "cocone_method.hpp"

namespace sculpt {

namespace tight_cocone_detail {

// Whether the triangles of `surface` around each sample make one closed fan: its link (the
// edges opposite it) is a single cycle, every link vertex on two link edges.
inline std::vector<bool> have_umbrellas(int samples, const std::vector<Facet<3>>& surface) {
  // Each sample's link edges, both ways round, in one array by sample.
  std::vector<int> first(samples + 1, 0);
  for (const auto& t : surface) {
    for (int v : t) first[v + 1] += 2;
  }
  for (int s = 0; s < samples; ++s) first[s + 1] += first[s];
  std::vector<std::pair<int, int>> ends(first.back());
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (const auto& t : surface) {
      for (int j = 0; j < 3; ++j) {
        const int a = t[(j + 1) % 3], b = t[(j + 2) % 3];
        ends[fill[t[j]]++] = {a, b};
        ends[fill[t[j]]++] = {b, a};
      }
    }
  }
  std::vector<bool> umbrella(samples, false);
  for (int s = 0; s < samples; ++s) {
    const auto begin = ends.begin() + first[s], end = ends.begin() + first[s + 1];
    const std::size_t size = static_cast<std::size_t>(end - begin);
    if (size < 2 * 3) continue;  // fewer than three link edges
    std::sort(begin, end);
    // Every link vertex has exactly two ends: its two neighbours in the cycle.
    bool cycle = true;
    for (std::size_t i = 0; i < size && cycle; i += 2) {
      cycle = begin[i].first == begin[i + 1].first &&
              (i + 2 == size || begin[i + 2].first != begin[i].first);
    }
    if (!cycle) continue;
    // Walk the cycle from one vertex: it must come back having seen every vertex of the link.
    const auto next = [&](int at, int from) {
      const auto it = std::lower_bound(begin, end, std::make_pair(at, INT_MIN));
      return it->second == from ? (it + 1)->second : it->second;
    };
    const int start = begin->first;
    const std::size_t vertices = size / 2;
    int previous = start, current = begin->second;
    std::size_t steps = 1;
    while (current != start && steps <= vertices) {
      const int following = next(current, previous);
      previous = current;
      current = following;
      ++steps;
    }
    umbrella[s] = current == start && steps == vertices;
  }
  return umbrella;
}

inline double squared_circumradius(const Point<3>& a, const Point<3>& b, const Point<3>& c) {
  using namespace extraction_detail;
  // |a-c|^2 |b-c|^2 |a-b|^2 / (4 |(a-c) x (b-c)|^2)
  const Vector u = minus(a, c), v = minus(b, c), w = minus(a, b);
  const Vector normal = cross(u, v);
  const double area2 = dot(normal, normal);
  return area2 > 0 ? dot(u, u) * dot(v, v) * dot(w, w) / (4 * area2) : INFINITY;
}

}  // namespace tight_cocone_detail

template <class Traits>
void run_tight_cocone_method(const typename Traits::Triangulation& triangulation,
                             Reconstruction<3>& result, Stage_clock& clock) {
  using namespace tight_cocone_detail;
  run_cocone_method<Traits>(triangulation, result, clock);

  clock.start("peeling");
  const int n = static_cast<int>(result.sample_count());
  std::vector<bool> good = have_umbrellas(n, result.surface);
  const auto is_good = [&](int site) { return site < n && good[site]; };

  std::vector<typename Traits::Triangulation::Vertex_handle> sample_vertex(n);
  for (auto vertex : triangulation.finite_vertex_handles()) {
    if (vertex->info() < n) sample_vertex[vertex->info()] = vertex;
  }
  // The co-cone's triangles, as the facets of the cells on both sides: bit i of a cell's entry
  // for its facet i (every triangle of the co-cone is a Delaunay facet).
  std::vector<std::uint8_t> in_initial(result.delaunay.cell_count, 0);
  for (const auto& t : result.surface) {
    typename Traits::Cell_handle cell;
    int i = 0, j = 0, k = 0;
    if (!triangulation.is_facet(sample_vertex[t[0]], sample_vertex[t[1]], sample_vertex[t[2]], cell,
                                i, j, k)) {
      continue;
    }
    const int facet = 6 - i - j - k;
    const auto mirror = cell->neighbor(facet);
    if (!triangulation.is_infinite(cell)) in_initial[cell->info()] |= 1u << facet;
    if (!triangulation.is_infinite(mirror)) in_initial[mirror->info()] |= 1u << mirror->index(cell);
  }
  std::vector<char> outside;
  const auto peel = [&] {
    outside.assign(result.delaunay.cell_count, 0);
    // A cell among bad samples only is peeled, but not through its smallest facet.
    std::vector<signed char> smallest(result.delaunay.cell_count, -1);
    for (auto cell : Traits::finite_cells(triangulation)) {
      bool all_bad = true;
      for (int i = 0; i < 4; ++i) all_bad = all_bad && !is_good(cell->vertex(i)->info());
      if (!all_bad) continue;
      double least = INFINITY;
      for (int i = 0; i < 4; ++i) {
        Point<3> p[3];
        for (int j = 0; j < 3; ++j) {
          p[j] = result.sites[cell->vertex(Traits::facet_vertex[i][j])->info()];
        }
        const double radius2 = squared_circumradius(p[0], p[1], p[2]);
        if (radius2 < least) least = radius2, smallest[cell->info()] = static_cast<signed char>(i);
      }
    }
    // The cells about a good sample on the side the peeling first reached it from, up to its
    // umbrella, are outside. Each good sample is marked once, from that first side, so an
    // arrival later from the inside (through a hole elsewhere) does not open its inner side.
    std::deque<typename Traits::Cell_handle> front;
    const auto peel_cell = [&](typename Traits::Cell_handle cell) {
      outside[cell->info()] = 1;
      front.push_back(cell);
    };
    std::vector<bool> visited(n, false);
    std::vector<typename Traits::Cell_handle> around;
    std::vector<int> walked_about(result.delaunay.cell_count, -1);  // the last sample's walk
    const auto mark_about = [&](typename Traits::Cell_handle start, int sample) {
      around.assign(1, start);
      walked_about[start->info()] = sample;
      while (!around.empty()) {
        const auto cell = around.back();
        around.pop_back();
        const int own = cell->index(sample_vertex[sample]);
        for (int i = 0; i < 4; ++i) {
          if (i == own) continue;  // the facet without the sample leaves its star
          const auto next = cell->neighbor(i);
          if (triangulation.is_infinite(next) || walked_about[next->info()] == sample) continue;
          if (in_initial[cell->info()] & (1u << i)) continue;  // its umbrella
          walked_about[next->info()] = sample;
          if (!outside[next->info()]) peel_cell(next);
          around.push_back(next);
        }
      }
    };
    for (auto cell : Traits::finite_cells(triangulation)) {
      bool box = false;
      for (int i = 0; i < 4; ++i) box = box || cell->vertex(i)->info() >= n;
      if (box) peel_cell(cell);
    }
    // How far: the good samples reached, each once (all of them on a closed surface).
    const double good_samples = static_cast<double>(std::count(good.begin(), good.end(), true));
    std::size_t popped = 0, reached_samples = 0;
    while (!front.empty()) {
      if (++popped % 16384 == 0 && good_samples > 0) {
        clock.report(std::min(1.0, double(reached_samples) / good_samples));
      }
      const auto cell = front.front();
      front.pop_front();
      for (int i = 0; i < 4; ++i) {
        const int site = cell->vertex(i)->info();
        if (!is_good(site) || visited[site]) continue;
        visited[site] = true;
        ++reached_samples;
        mark_about(cell, site);
      }
      for (int i = 0; i < 4; ++i) {
        const auto next = cell->neighbor(i);
        if (triangulation.is_infinite(next) || outside[next->info()]) continue;
        // Among bad samples: into the neighbour, but not through its smallest facet.
        if (smallest[next->info()] >= 0 && next->index(cell) != smallest[next->info()]) {
          peel_cell(next);
        }
      }
    }
  };
  peel();
  // A good sample that no outside cell reached lies behind an umbrella facing nothing: bad.
  std::vector<bool> reached(n, false);
  for (auto cell : Traits::finite_cells(triangulation)) {
    if (!outside[cell->info()]) continue;
    for (int i = 0; i < 4; ++i) {
      const int site = cell->vertex(i)->info();
      if (site < n) reached[site] = true;
    }
  }
  bool changed = false;
  for (int s = 0; s < n; ++s) {
    if (good[s] && !reached[s]) good[s] = false, changed = true;
  }
  if (changed) peel();
  for (int s = 0; s < n; ++s) {
    if (!good[s]) result.candidates.without_umbrella.push_back(s);
  }
  result.stats.samples_without_umbrella = result.candidates.without_umbrella.size();

  const auto in_solid = [&](auto cell) { return !outside[cell->info()]; };
  clock.start("solid");
  collect_solid<Traits>(triangulation, in_solid, result);
  clock.start("surface");
  result.surface.clear();
  collect_skin<Traits>(triangulation, in_solid, result);
}

}  // namespace sculpt
