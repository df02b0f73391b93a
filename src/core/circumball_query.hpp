// SPDX-License-Identifier: GPL-3.0-or-later
// Which all-sample cells of DT(S ∪ BBV) a set of poles would destroy if they were inserted, as
// the paper's sculpting inserts the outer concave poles (section 3.2), found without inserting.
//
// Inserting points P destroys exactly the cells whose circumball holds a point of P, and every
// all-sample cell of DT(S ∪ BBV ∪ P) is already a cell of DT(S ∪ BBV) (a ball empty of more
// points is empty of fewer). So the all-sample cells that survive are read off the first
// triangulation with one query per cell: a k-d tree of P finds the points near the cell's
// circumball, and CGAL's exact in-sphere predicate decides for each. With `perturbed`, a point on
// the sphere counts as CGAL's insertion counts it (its symbolic perturbation), so the answer is
// the insertion's also for cospherical points; without, only points strictly inside count.
//
// The k-d tree is searched with the floating-point circumcentre, so the search ball is widened
// by more than that centre's error. When the cell is so flat that the error could exceed the
// widening (its orientation determinant below 1e-6 of the product of its edge lengths, where
// the centre's relative error can reach ~1e-10), the exact circumcentre is used instead.
#pragma once

#include <algorithm>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "point_tree.hpp"

namespace sculpt {

// The squared distance from a cell's circumcentre (as Traits::circumcenter gives it) to its
// first vertex.
template <class Traits>
double squared_circumradius(typename Traits::Cell_handle cell,
                            const Point<Traits::dimension>& center) {
  const Point<Traits::dimension> corner = Traits::from_cgal(cell->vertex(0)->point());
  double r2 = 0;
  for (int k = 0; k < Traits::dimension; ++k)
    r2 += (center[k] - corner[k]) * (center[k] - corner[k]);
  return r2;
}

template <class Traits>
class Circumball_query {
  static constexpr int D = Traits::dimension;
  using Triangulation = typename Traits::Triangulation;
  using Cell_handle = typename Traits::Cell_handle;

 public:
  // The points [first, last) are copied.
  Circumball_query(const Triangulation& triangulation, const Point<D>* first, const Point<D>* last,
                   bool perturbed)
      : triangulation_(triangulation),
        tree_(first, last),
        empty_(first == last),
        perturbed_(perturbed) {}
  Circumball_query(const Triangulation& triangulation, const std::vector<Point<D>>& points,
                   bool perturbed)
      : Circumball_query(triangulation, points.data(), points.data() + points.size(), perturbed) {}

  // Whether a point lies in the circumball of `cell`, whose circumcentre Traits::circumcenter
  // gave as `center`.
  bool holds_point(Cell_handle cell, const Point<D>& center) const {
    return holds_point(cell, center, [](int, double) { return true; });
  }

  // Whether a point i with counts(i, r) true lies in the circumball of `cell` (i: its index
  // among the points given; r: the circumradius, measured from the centre searched with).
  template <class Counts>
  bool holds_point(Cell_handle cell, const Point<D>& center, Counts&& counts) const {
    if (empty_) return false;
    const Point<D> search_center = well_conditioned(cell) ? center : exact_center(cell);
    double size = 0;
    for (int k = 0; k < D; ++k) size = std::max(size, std::abs(search_center[k]));
    const double r = std::sqrt(squared_circumradius<Traits>(cell, search_center));
    const double widened = r + 1e-6 * r + 1e-14 * size;
    return tree_.any_within_indexed(
        search_center, widened * widened, [&](const Point<D>& p, int i) {
          return counts(i, r) &&
                 Traits::in_circumball(triangulation_, cell, Traits::to_cgal(p), perturbed_);
        });
  }

 private:
  // |det(v1 - v0, ..., vD - v0)| against the product of those edge lengths (Hadamard's bound).
  static bool well_conditioned(Cell_handle cell) {
    Point<D> edge[D];
    const Point<D> v0 = Traits::from_cgal(cell->vertex(0)->point());
    double product = 1;
    for (int i = 0; i < D; ++i) {
      const Point<D> v = Traits::from_cgal(cell->vertex(i + 1)->point());
      double length2 = 0;
      for (int k = 0; k < D; ++k) {
        edge[i][k] = v[k] - v0[k];
        length2 += edge[i][k] * edge[i][k];
      }
      product *= std::sqrt(length2);
    }
    double det;
    if constexpr (D == 2) {
      det = edge[0][0] * edge[1][1] - edge[0][1] * edge[1][0];
    } else {
      det = edge[0][0] * (edge[1][1] * edge[2][2] - edge[1][2] * edge[2][1]) -
            edge[0][1] * (edge[1][0] * edge[2][2] - edge[1][2] * edge[2][0]) +
            edge[0][2] * (edge[1][0] * edge[2][1] - edge[1][1] * edge[2][0]);
    }
    return std::abs(det) >= 1e-6 * product && std::isfinite(product);
  }

  static Point<D> exact_center(Cell_handle cell) {
    return Traits::from_cgal(Traits::exact_circumcenter(cell));
  }

  const Triangulation& triangulation_;
  Point_tree<D> tree_;
  bool empty_;
  bool perturbed_;
};

}  // namespace sculpt
