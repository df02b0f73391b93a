// SPDX-License-Identifier: GPL-3.0-or-later
// Checks shared by the tests: what makes a reconstructed curve or surface right.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sculpt/sculpt.hpp>
#include <set>
#include <utility>
#include <vector>

#include "core/stage_clock.hpp"

namespace sculpt::testing {

// A stage clock that tells no one, for calling a stage's function on its own.
struct Silent_clock {
  Statistics stats;
  Options options;
  Stage_clock clock{stats, options};
};

// The diagonal of the points' bounding box.
template <int D>
double box_diagonal(const std::vector<Point<D>>& points) {
  Point<D> lower = points[0], upper = points[0];
  for (const auto& p : points) {
    for (int k = 0; k < D; ++k)
      lower[k] = std::min(lower[k], p[k]), upper[k] = std::max(upper[k], p[k]);
  }
  double sum = 0;
  for (int k = 0; k < D; ++k) sum += (upper[k] - lower[k]) * (upper[k] - lower[k]);
  return std::sqrt(sum);
}

// The default options with another method.
inline Options with_method(Method method) {
  Options options;
  options.method = method;
  return options;
}

// Every method that reconstructs in this dimension, in the order of method_names().
inline std::vector<Method> methods_in(int dimension) {
  std::vector<Method> methods;
  for (const char* name : method_names()) {
    Method method;
    if (parse_method(name, method) && reconstructs_in(method, dimension)) methods.push_back(method);
  }
  return methods;
}

// The faces of tetrahedra, each with the number of tetrahedra it bounds.
inline std::map<std::array<int, 3>, int> faces_of(const std::vector<Cell<3>>& cells) {
  std::map<std::array<int, 3>, int> faces;
  for (const auto& cell : cells) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face;
      for (int j = 0, k = 0; j < 4; ++j) {
        if (j != skip) face[k++] = cell[j];
      }
      std::sort(face.begin(), face.end());
      ++faces[face];
    }
  }
  return faces;
}

// Triangles as vertex sets, whatever their orientation.
inline std::set<std::array<int, 3>> unordered(const std::vector<Facet<3>>& triangles) {
  std::set<std::array<int, 3>> result;
  for (auto t : triangles) {
    std::sort(t.begin(), t.end());
    result.insert(t);
  }
  return result;
}

// The edges on one triangle only: a surface's border.
inline std::set<std::pair<int, int>> border_edges(const std::vector<Facet<3>>& triangles) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) ++count[std::minmax(t[j], t[(j + 1) % 3])];
  }
  std::set<std::pair<int, int>> edges;
  for (const auto& [edge, times] : count) {
    if (times == 1) edges.insert(edge);
  }
  return edges;
}

inline std::set<std::pair<int, int>> undirected(const std::vector<Facet<2>>& edges) {
  std::set<std::pair<int, int>> result;
  for (const auto& e : edges) result.insert(std::minmax(e[0], e[1]));
  return result;
}

inline std::set<std::pair<int, int>> directed(const std::vector<Facet<2>>& edges) {
  std::set<std::pair<int, int>> result;
  for (const auto& e : edges) result.insert({e[0], e[1]});
  return result;
}

// Every directed edge of the triangles appears once, and its reverse once: a closed surface
// whose triangles are consistently oriented.
inline ::testing::AssertionResult consistently_oriented_closed(
    const std::vector<Facet<3>>& triangles) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : triangles) {
    for (int j = 0; j < 3; ++j) ++count[{t[j], t[(j + 1) % 3]}];
  }
  for (const auto& [edge, times] : count) {
    if (times != 1) {
      return ::testing::AssertionFailure() << "directed edge " << edge.first << "-" << edge.second
                                           << " appears " << times << " times";
    }
    if (!count.count({edge.second, edge.first})) {
      return ::testing::AssertionFailure()
             << "edge " << edge.first << "-" << edge.second << " has no opposite";
    }
  }
  return ::testing::AssertionSuccess();
}

// Volume enclosed by the triangles (divergence theorem): positive when normals point outward.
inline double signed_volume(const std::vector<Point<3>>& points,
                            const std::vector<Facet<3>>& triangles) {
  double volume = 0;
  for (const auto& t : triangles) {
    const auto& a = points[t[0]];
    const auto& b = points[t[1]];
    const auto& c = points[t[2]];
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6.0;
}

// Everything a closed, outward-oriented 2-manifold reconstruction of the samples must satisfy.
inline void expect_closed_manifold(const Reconstruction<3>& r, long euler_characteristic) {
  const auto& s = r.stats;
  EXPECT_GT(s.facets, 0u);
  EXPECT_EQ(s.boundary_ridges, 0u);
  EXPECT_EQ(s.non_manifold_ridges, 0u);
  EXPECT_EQ(s.non_manifold_vertices, 0u);
  EXPECT_EQ(s.components, 1u);
  EXPECT_EQ(s.unused_samples, 0u);
  EXPECT_EQ(s.euler_characteristic, euler_characteristic);
  EXPECT_TRUE(consistently_oriented_closed(r.surface));
  const std::vector<Point<3>> samples(r.sites.begin(), r.sites.begin() + r.sample_count());
  EXPECT_GT(signed_volume(samples, r.surface), 0.0) << "normals point inward";
  for (const auto& t : r.surface) {
    for (int v : t) ASSERT_LT(v, static_cast<int>(r.sample_count()));
  }
}

// Every cell of a CGAL triangulation (face in 2D) whose vertices carry an int info, in the
// container's order, as its vertices' infos (-1 for the infinite vertex): two triangulations
// built alike give the same list.
template <int D, class Triangulation>
std::vector<int> cells_as_vertex_infos(const Triangulation& t) {
  std::vector<int> infos;
  const auto add = [&](auto cell) {
    for (int i = 0; i <= D; ++i) {
      infos.push_back(t.is_infinite(cell->vertex(i)) ? -1 : cell->vertex(i)->info());
    }
  };
  if constexpr (D == 3) {
    for (auto cell : t.all_cell_handles()) add(cell);
  } else {
    for (auto face : t.all_face_handles()) add(face);
  }
  return infos;
}

}  // namespace sculpt::testing
