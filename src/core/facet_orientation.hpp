// SPDX-License-Identifier: GPL-3.0-or-later
// Which vertices of a cell make its facets, in the order that faces away from the cell: the
// convention of CGAL's positively oriented cells (counterclockwise faces in 2D), shared by the
// core (surface extraction) and the scene layer (the hull), which needs no CGAL.
#pragma once

namespace sculpt {

template <int D>
struct Facet_orientation;

// Edge opposite vertex i of a counterclockwise triangle, with the triangle on its left.
template <>
struct Facet_orientation<2> {
  static constexpr int vertex[3][2] = {{1, 2}, {2, 0}, {0, 1}};
};

// Triangle opposite vertex i of a positively oriented tetrahedron, its normal pointing away
// from vertex i: (a, b, c, i) is an odd permutation of (0, 1, 2, 3) for each row.
template <>
struct Facet_orientation<3> {
  static constexpr int vertex[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
};

}  // namespace sculpt
