// SPDX-License-Identifier: GPL-3.0-or-later
// How noisy the samples are, in units of their own spacing: a scale-free number the verdict
// reports and the automatic cleaning acts on (driver/cleaning.hpp).
//
// Around each sample, its 15 nearest samples (itself among them) are put in a local frame, the
// plane (line, in 2D) that fits them best, and their heights over it fitted with a quadric
// h = c0 + c1 u + c2 v + c3 u^2 + c4 u v + c5 v^2 (a parabola in 2D), as a jet fit does (Cazals &
// Pouget 2005). What the quadric cannot follow, the root mean square of the residuals over the
// degrees of freedom left, is the sample's roughness: curvature is followed, noise is not. Its
// spacing is the mean distance to its three nearest others.
//
// Noise roughens every sample; a sharp edge or a feature sampled too coarsely for a quadric
// roughens only the samples near it. So the noise is read off the smooth end: the roughness over
// spacing that 90% of the samples exceed, divided by 0.68, its share of the noise for Gaussian
// noise across the surface (spheres of 20,000 and 50,000 samples with noise of 0.1, 0.3 and 0.5
// of the spacing measure 0.12, 0.33 and 0.48). Smooth samples measure 0; CGAL's coarse meshes at
// most 0.13 (bull; femur 0.07), its CAD parts 0. Measured on up to 20,000 samples spread through
// the input (a stride); the tree holds all. Fewer than 100 samples are too few for neighbourhoods
// of 15 to be local: not measured. Neither are samples whose neighbourhood is a rod, a tube
// only a few samples round (a sparsely sampled thin torus measured 0.6 of its spacing, and
// cleaning it closed its hole): too coarse to tell noise from the tube's curvature. Nor those
// whose neighbours lie on both sides of a wall thinner than the neighbourhood (two_sheets.hpp):
// what the quadric leaves there is the wall's thickness.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "point_tree.hpp"
#include "quadric_fit.hpp"
#include "two_sheets.hpp"

namespace sculpt {

// The three eigenvalues of a symmetric 3x3 matrix, smallest first, by Smith's trigonometric
// formula (1961).
inline std::array<double, 3> eigenvalues(const double m[3][3]) {
  const double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
  if (off == 0) {
    std::array<double, 3> diagonal{m[0][0], m[1][1], m[2][2]};
    std::sort(diagonal.begin(), diagonal.end());
    return diagonal;
  }
  const double q = (m[0][0] + m[1][1] + m[2][2]) / 3;
  const double p2 = (m[0][0] - q) * (m[0][0] - q) + (m[1][1] - q) * (m[1][1] - q) +
                    (m[2][2] - q) * (m[2][2] - q) + 2 * off;
  const double p = std::sqrt(p2 / 6);
  double b[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) b[i][j] = (m[i][j] - (i == j ? q : 0)) / p;
  }
  const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                     b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                     b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  const double phi = std::acos(std::clamp(det / 2, -1.0, 1.0)) / 3;
  const double largest = q + 2 * p * std::cos(phi);
  const double smallest = q + 2 * p * std::cos(phi + 2 * M_PI / 3);
  return {smallest, 3 * q - largest - smallest, largest};
}

// The smallest eigenvalue of a symmetric matrix (2x2: a b / b c; 3x3: eigenvalues above).
inline double smallest_eigenvalue(const double m[3][3], int dimension) {
  if (dimension == 2) {
    const double mean = (m[0][0] + m[1][1]) / 2, half = (m[0][0] - m[1][1]) / 2;
    return mean - std::sqrt(half * half + m[0][1] * m[0][1]);
  }
  return eigenvalues(m)[0];
}

// A unit vector along which the symmetric 3x3 matrix m has eigenvalue `value`: the largest
// cross product of two rows of m - value I (their common normal).
inline Point<3> eigenvector(const double m[3][3], double value) {
  double r[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = m[i][j] - (i == j ? value : 0);
  }
  Point<3> best{0, 0, 1};
  double best_length = 0;
  for (int i = 0; i < 3; ++i) {
    const double* a = r[i];
    const double* b = r[(i + 1) % 3];
    const Point<3> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]};
    const double length = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (length > best_length) {
      best_length = length;
      best = {c[0] / length, c[1] / length, c[2] / length};
    }
  }
  return best;
}

// One sample's roughness: the residual of the quadric fitted to its neighbours' heights over
// their best plane (line); -1 when the fit is degenerate or (3D) the neighbourhood is a tube
// too thin for its sampling.
template <int D>
double roughness(const std::vector<Point<D>>& samples, const std::vector<int>& near) {
  const double count = static_cast<double>(near.size());
  Point<D> mean{};
  for (int j : near) {
    for (int k = 0; k < D; ++k) mean[k] += samples[j][k] / count;
  }
  double covariance[3][3] = {};
  for (int j : near) {
    for (int a = 0; a < D; ++a) {
      for (int b = 0; b < D; ++b)
        covariance[a][b] += (samples[j][a] - mean[a]) * (samples[j][b] - mean[b]) / count;
    }
  }
  // The frame: the normal (least variance) and, across it, the tangent directions.
  Point<3> normal{}, tangent_u{}, tangent_v{};
  if constexpr (D == 3) {
    // A neighbourhood shaped like a rod (long one way, round across it) is a tube thinner than
    // the sampling, a few samples around it: no surface patch to read noise off, whatever the
    // quadric makes of it. (A noisy sheet is wide both ways across its normal.)
    const auto variance = eigenvalues(covariance);
    if (variance[1] < 0.5 * variance[2] && variance[0] > 0.25 * variance[1]) return -1;
    normal = eigenvector(covariance, variance[0]);
    const Point<3> helper = std::abs(normal[0]) < 0.9 ? Point<3>{1, 0, 0} : Point<3>{0, 1, 0};
    tangent_u = {helper[1] * normal[2] - helper[2] * normal[1],
                 helper[2] * normal[0] - helper[0] * normal[2],
                 helper[0] * normal[1] - helper[1] * normal[0]};
    const double length = std::sqrt(tangent_u[0] * tangent_u[0] + tangent_u[1] * tangent_u[1] +
                                    tangent_u[2] * tangent_u[2]);
    for (double& x : tangent_u) x /= length;
    tangent_v = {normal[1] * tangent_u[2] - normal[2] * tangent_u[1],
                 normal[2] * tangent_u[0] - normal[0] * tangent_u[2],
                 normal[0] * tangent_u[1] - normal[1] * tangent_u[0]};
  } else {
    const double lambda = smallest_eigenvalue(covariance, 2);
    // (a - l) x + b y = 0: the normal is (b, l - a) or, where that vanishes, (l - c, b).
    double nx = covariance[0][1], ny = lambda - covariance[0][0];
    if (std::abs(nx) + std::abs(ny) < 1e-300) {
      nx = lambda - covariance[1][1];
      ny = covariance[0][1];
    }
    if (std::abs(nx) + std::abs(ny) < 1e-300) nx = 1;  // isotropic: any direction
    const double length = std::hypot(nx, ny);
    normal = {nx / length, ny / length, 0};
    tangent_u = {-normal[1], normal[0], 0};
  }
  // In units of the neighbourhood's size, so that the fit's conditioning (and its test for a
  // degenerate system) is the same at any scale of the coordinates.
  const double size = std::sqrt(covariance[0][0] + covariance[1][1] + covariance[2][2]);
  if (!(size > 0)) return -1;
  // Least squares of h over the monomials 1, u, v, u^2, u v, v^2 (1, u, u^2 in 2D).
  constexpr int terms = D == 3 ? 6 : 3;
  double normal_matrix[6][6] = {}, right[6] = {};
  std::vector<std::array<double, 7>> rows;  // the monomials, then h
  rows.reserve(near.size());
  for (int j : near) {
    double u = 0, v = 0, h = 0;
    for (int k = 0; k < D; ++k) {
      const double d = samples[j][k] - mean[k];
      u += d * tangent_u[k] / size;
      v += d * tangent_v[k] / size;
      h += d * normal[k] / size;
    }
    std::array<double, 7> row{};
    if constexpr (D == 3) {
      row = {1, u, v, u * u, u * v, v * v, h};
    } else {
      row = {1, u, u * u, h, 0, 0, 0};
    }
    for (int a = 0; a < terms; ++a) {
      for (int b = 0; b < terms; ++b) normal_matrix[a][b] += row[a] * row[b];
      right[a] += row[a] * row[terms];
    }
    rows.push_back(row);
  }
  if (!solve_small(normal_matrix, right, terms)) return -1;
  double squares = 0;
  for (const auto& row : rows) {
    double fitted = 0;
    for (int a = 0; a < terms; ++a) fitted += right[a] * row[a];
    squares += (row[terms] - fitted) * (row[terms] - fitted);
  }
  // Both sides of a wall thinner than the neighbourhood: what the quadric leaves is the wall's
  // thickness, not noise (two_sheets.hpp). Left out, as a thin tube is: what two sheets fitted
  // apart leave would read the noise low wherever one noisy sheet splits by chance, and the
  // smooth end of the measure is made of the lowest readings.
  if constexpr (D == 3) {
    std::vector<std::array<double, 3>> local;
    local.reserve(rows.size());
    for (const auto& row : rows) local.push_back({row[1], row[2], row[terms]});
    if (lie_on_two_sheets(local)) return -1;
  }
  return size * std::sqrt(squares / (count - terms));
}

struct Noise_measure {
  double noise = -1;   // over the spacing; -1: not measured
  double spacing = 0;  // the median spacing of the samples measured
};

// The samples' noise over their spacing (see the top); not measured for fewer than 100 samples
// or a coordinate that is not finite (the input checks refuse those).
template <int D>
Noise_measure measure_noise(const std::vector<Point<D>>& samples) {
  constexpr int neighbours = 15;
  constexpr std::size_t most_measured = 20000;
  if (samples.size() < 100) return {};
  for (const auto& p : samples) {
    for (double x : p) {
      if (!std::isfinite(x)) return {};
    }
  }
  const Point_tree<D> tree(samples.data(), samples.data() + samples.size());
  const std::size_t stride = std::max<std::size_t>(1, samples.size() / most_measured);
  std::vector<double> ratios, spacings;
  ratios.reserve(samples.size() / stride + 1);
  spacings.reserve(samples.size() / stride + 1);
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    const std::vector<int> near = tree.k_nearest_to(samples[i], neighbours);
    double spacing = 0;
    for (int j = 1; j <= 3 && j < static_cast<int>(near.size()); ++j) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) {
        d2 += (samples[near[j]][k] - samples[i][k]) * (samples[near[j]][k] - samples[i][k]);
      }
      spacing += std::sqrt(d2) / 3;
    }
    const double rough = roughness<D>(samples, near);
    if (spacing > 0 && rough >= 0) {
      ratios.push_back(rough / spacing);
      spacings.push_back(spacing);
    }
  }
  // Mostly thin tubes (or degenerate): too little surface to tell noise from sparse sampling.
  if (ratios.size() < std::max<std::size_t>(20, samples.size() / stride / 3)) return {};
  const auto smooth_end = ratios.begin() + static_cast<long>(ratios.size() / 10);
  std::nth_element(ratios.begin(), smooth_end, ratios.end());
  const auto middle = spacings.begin() + static_cast<long>(spacings.size() / 2);
  std::nth_element(spacings.begin(), middle, spacings.end());
  return {*smooth_end / 0.68, *middle};
}

}  // namespace sculpt
