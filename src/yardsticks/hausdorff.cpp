// SPDX-License-Identifier: GPL-3.0-or-later
// The two-sided Hausdorff distance between two triangle meshes, the measure of `sculpt compare`
// against a reference mesh. Each side is sampled (every vertex, every edge's midpoint, every
// triangle's centroid, and a finer barycentric grid on triangles long against the meshes' size),
// and each sample's distance to the other mesh is exact, by CGAL's AABB tree. Sampling can only
// miss a farther point, so the value is a lower bound, tight to the grid's spacing.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using Triangles = std::vector<Triangle>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Samples along a triangle's sides finer than this many per diagonal of the meshes' box.
constexpr double grid_per_diagonal = 400;
constexpr int finest_grid = 32;  // subdivisions of a side, at most

Triangles triangles_of(const std::vector<Point<3>>& points, const std::vector<Facet<3>>& facets) {
  Triangles triangles;
  triangles.reserve(facets.size());
  for (const auto& f : facets) {
    const auto p = [&](int k) {
      const auto& q = points[static_cast<std::size_t>(f[k])];
      return Kernel::Point_3(q[0], q[1], q[2]);
    };
    Triangle t(p(0), p(1), p(2));
    if (!t.is_degenerate()) triangles.push_back(t);  // no area: its sides are others' too
  }
  return triangles;
}

// The farthest any sample of `from` lies from the triangles of `to`.
double one_sided(const Triangles& from, const Triangles& to, double spacing) {
  Tree tree(to.begin(), to.end());
  tree.accelerate_distance_queries();
  double farthest = 0;
  const auto measure = [&](const Kernel::Point_3& p) {
    farthest = std::max(farthest, tree.squared_distance(p));
  };
  for (const auto& t : from) {
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
      longest = std::max(longest, CGAL::squared_distance(t[k], t[(k + 1) % 3]));
    }
    longest = std::sqrt(longest);
    const int grid = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 2, finest_grid);
    for (int i = 0; i <= grid; ++i) {
      for (int j = 0; i + j <= grid; ++j) {
        const double a = double(i) / grid, b = double(j) / grid, c = 1 - a - b;
        measure(Kernel::Point_3(a * t[0].x() + b * t[1].x() + c * t[2].x(),
                                a * t[0].y() + b * t[1].y() + c * t[2].y(),
                                a * t[0].z() + b * t[1].z() + c * t[2].z()));
      }
    }
    measure(CGAL::centroid(t));
  }
  return std::sqrt(farthest);
}

}  // namespace

double hausdorff_distance(const std::vector<Point<3>>& a_points, const std::vector<Facet<3>>& a,
                          const std::vector<Point<3>>& b_points, const std::vector<Facet<3>>& b) {
  const Triangles first = triangles_of(a_points, a), second = triangles_of(b_points, b);
  if (first.empty() || second.empty()) return std::numeric_limits<double>::infinity();
  CGAL::Bbox_3 box;
  for (const auto& t : first) box += t.bbox();
  for (const auto& t : second) box += t.bbox();
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const double spacing = std::max(diagonal / grid_per_diagonal, std::numeric_limits<double>::min());
  return std::max(one_sided(first, second, spacing), one_sided(second, first, spacing));
}

}  // namespace sculpt
