// The one place the 2D algorithm is compiled: everything else links against it.
#include "traits_2.hpp"
// The traits come first: the generic core uses the CGAL headers they include.
#include "../core/reconstruction.hpp"

namespace sculpt {

int Traits_2::affine_dimension(const std::vector<Cgal_point>& points) {
  const auto distinct = std::find_if(points.begin(), points.end(),
                                     [&](const Cgal_point& p) { return p != points.front(); });
  if (distinct == points.end()) return 0;
  const auto off_line = std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) {
    return !CGAL::collinear(points.front(), *distinct, p);
  });
  return off_line == points.end() ? 1 : 2;
}

Reconstruction<2> reconstruct(const std::vector<Point<2>>& samples, const Options& options) {
  return reconstruct_with<Traits_2>(samples, options);
}

double delaunay_seconds(const std::vector<Point<2>>& points) {
  return time_plain_delaunay<Traits_2>(points);
}

}  // namespace sculpt
