// SPDX-License-Identifier: GPL-3.0-or-later
// Small geometric helpers of the scene layer, in plain doubles (the pictures need no exactness).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "scene.hpp"

namespace sculpt::scene {

// Centre of the circle (D = 2) or sphere (D = 3) through the corners of a simplex: the point x
// with |x - c0|^2 = |x - ci|^2, a linear system in x - c0 solved by Cramer's rule.
template <int D>
Point<D> circumcenter(const std::array<Point<D>, D + 1>& corners) {
  double a[D][D], b[D];
  for (int i = 0; i < D; ++i) {
    b[i] = 0;
    for (int k = 0; k < D; ++k) {
      a[i][k] = corners[i + 1][k] - corners[0][k];
      b[i] += 0.5 * a[i][k] * a[i][k];
    }
  }
  Point<D> x = corners[0];
  if constexpr (D == 2) {
    const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    x[0] += (b[0] * a[1][1] - a[0][1] * b[1]) / det;
    x[1] += (a[0][0] * b[1] - b[0] * a[1][0]) / det;
  } else {
    const auto det3 = [](const double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double det = det3(a);
    for (int k = 0; k < 3; ++k) {
      double m[3][3];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
      }
      x[k] += det3(m) / det;
    }
  }
  return x;
}

// Pairs of cells that share a facet.
template <int D>
std::vector<std::pair<int, int>> cells_sharing_a_facet(const std::vector<Cell<D>>& cells) {
  std::vector<std::pair<std::array<int, D>, int>> facets;
  facets.reserve(cells.size() * (D + 1));
  for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
    for (int skip = 0; skip <= D; ++skip) {
      std::array<int, D> facet;
      for (int i = 0, k = 0; i <= D; ++i) {
        if (i != skip) facet[k++] = cells[c][i];
      }
      std::sort(facet.begin(), facet.end());
      facets.emplace_back(facet, c);
    }
  }
  std::sort(facets.begin(), facets.end());
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i + 1 < facets.size(); ++i) {
    if (facets[i].first == facets[i + 1].first)
      pairs.emplace_back(facets[i].second, facets[i + 1].second);
  }
  return pairs;
}

// Area-weighted vertex normals, one per triangle corner, for smooth shading.
inline std::vector<Vec3> vertex_normals(const std::vector<Point<3>>& sites,
                                        const std::vector<Facet<3>>& triangles, int samples) {
  std::vector<std::array<double, 3>> sum(samples, {0, 0, 0});
  for (const auto& t : triangles) {
    const auto& a = sites[t[0]];
    const auto& b = sites[t[1]];
    const auto& c = sites[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    for (int s : t) {
      for (int k = 0; k < 3; ++k) sum[s][k] += n[k];
    }
  }
  std::vector<Vec3> normals;
  normals.reserve(triangles.size() * 3);
  for (const auto& t : triangles) {
    for (int s : t) {
      const double length =
          std::sqrt(sum[s][0] * sum[s][0] + sum[s][1] * sum[s][1] + sum[s][2] * sum[s][2]);
      const double scale = length > 0 ? 1.0 / length : 0.0;
      normals.push_back(
          {float(sum[s][0] * scale), float(sum[s][1] * scale), float(sum[s][2] * scale)});
    }
  }
  return normals;
}

}  // namespace sculpt::scene
