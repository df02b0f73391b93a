// SPDX-License-Identifier: GPL-3.0-or-later
// A quadric h = c0 + c1 u + c2 v + c3 u^2 + c4 u v + c5 v^2 fitted by least squares to points
// given in a local frame (u, v across the best plane, h along its normal), as a jet fit does
// (Cazals & Pouget 2005), and the small linear systems it needs.
#pragma once

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace sculpt {

// Solves the n x n system a x = b (n <= 6) by Gaussian elimination with partial pivoting;
// false when it is singular (the neighbours are degenerate: collinear, coincident).
inline bool solve_small(double a[6][6], double b[6], int n) {
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int row = col + 1; row < n; ++row) {
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    }
    if (std::abs(a[pivot][col]) < 1e-12) return false;
    std::swap(a[pivot], a[col]);
    std::swap(b[pivot], b[col]);
    for (int row = col + 1; row < n; ++row) {
      const double factor = a[row][col] / a[col][col];
      for (int k = col; k < n; ++k) a[row][k] -= factor * a[col][k];
      b[row] -= factor * b[col];
    }
  }
  for (int row = n - 1; row >= 0; --row) {
    for (int k = row + 1; k < n; ++k) b[row] -= a[row][k] * b[k];
    b[row] /= a[row][row];
  }
  return true;
}

// The quadric's six coefficients of least squares over the points' (u, v) and the heights given
// (their own h, or what is left of it); false when the points are degenerate.
inline bool fit_quadric(const std::vector<std::array<double, 3>>& points,
                        const std::vector<double>& heights, double coefficients[6]) {
  double matrix[6][6] = {};
  for (int a = 0; a < 6; ++a) coefficients[a] = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const auto& p = points[j];
    const double row[6] = {1, p[0], p[1], p[0] * p[0], p[0] * p[1], p[1] * p[1]};
    for (int a = 0; a < 6; ++a) {
      for (int b = 0; b < 6; ++b) matrix[a][b] += row[a] * row[b];
      coefficients[a] += row[a] * heights[j];
    }
  }
  return solve_small(matrix, coefficients, 6);
}

inline double quadric_at(const double c[6], double u, double v) {
  return c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
}

}  // namespace sculpt
