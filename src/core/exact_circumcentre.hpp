// SPDX-License-Identifier: GPL-3.0-or-later
// The circumcentre of a Delaunay cell, as every stage measures with: CGAL's floating-point
// construction, except for a cell so flat that its floating-point denominator vanishes (CGAL
// asserts, or divides by zero when its assertions are compiled out) or its centre overflows.
// The triangulation's exact predicates say such a cell is not degenerate, so its centre exists:
// it is computed with rationals and rounded. Found by fuzzing the reconstruction on points whose
// coordinates are ~1e-108 apart after normalisation (fuzz/regressions/reconstruct).
#pragma once

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/exceptions.h>

#include <cmath>

namespace sculpt {

using Exact_rational_kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;

// The exact circumcentres, rounded to doubles.
template <class Cgal_point>
Cgal_point exact_circumcentre(const Cgal_point& a, const Cgal_point& b, const Cgal_point& c) {
  using P = Exact_rational_kernel::Point_2;
  const P centre = CGAL::circumcenter(P(a.x(), a.y()), P(b.x(), b.y()), P(c.x(), c.y()));
  return Cgal_point(CGAL::to_double(centre.x()), CGAL::to_double(centre.y()));
}

template <class Cgal_point>
Cgal_point exact_circumcentre(const Cgal_point& a, const Cgal_point& b, const Cgal_point& c,
                              const Cgal_point& d) {
  using P = Exact_rational_kernel::Point_3;
  const auto exact = [](const Cgal_point& p) { return P(p.x(), p.y(), p.z()); };
  const P centre = CGAL::circumcenter(exact(a), exact(b), exact(c), exact(d));
  return Cgal_point(CGAL::to_double(centre.x()), CGAL::to_double(centre.y()),
                    CGAL::to_double(centre.z()));
}

template <class Cgal_point, class Inexact, class Exact>
Cgal_point circumcentre_or_exact(Inexact&& inexact, Exact&& exact) {
  try {
    const Cgal_point centre = inexact();
    bool finite = true;
    for (int k = 0; k < Cgal_point::Ambient_dimension::value; ++k) {
      finite = finite && std::isfinite(centre[k]);
    }
    if (finite) return centre;
  } catch (const CGAL::Assertion_exception&) {
    // CGAL's kernel assertion on a vanishing denominator (builds with assertions on)
  }
  return exact();
}

}  // namespace sculpt
