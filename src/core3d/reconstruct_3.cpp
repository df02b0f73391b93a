// The one place the 3D algorithm is compiled: everything else links against it.
#include "traits_3.hpp"
// The traits come first: the generic core uses the CGAL headers they include.
#include "../core/reconstruction.hpp"

namespace sculpt {

int Traits_3::affine_dimension(const std::vector<Cgal_point>& points) {
  const auto distinct = std::find_if(points.begin(), points.end(),
                                     [&](const Cgal_point& p) { return p != points.front(); });
  if (distinct == points.end()) return 0;
  const auto off_line = std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) {
    return !CGAL::collinear(points.front(), *distinct, p);
  });
  if (off_line == points.end()) return 1;
  const auto off_plane = std::find_if(points.begin(), points.end(), [&](const Cgal_point& p) {
    return !CGAL::coplanar(points.front(), *distinct, *off_line, p);
  });
  return off_plane == points.end() ? 2 : 3;
}

Reconstruction<3> reconstruct(const std::vector<Point<3>>& samples, const Options& options) {
  return reconstruct_with<Traits_3>(samples, options);
}

double delaunay_seconds(const std::vector<Point<3>>& points) {
  return time_plain_delaunay<Traits_3>(points);
}

}  // namespace sculpt
