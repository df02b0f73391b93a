// SPDX-License-Identifier: GPL-3.0-or-later
// What the benchmark measures Sculpt against, on the same points: CGAL's Delaunay triangulation
// (plain vertices and cells, no information attached: the leanest CGAL offers) and CGAL's
// Advancing Front Surface Reconstruction with its default parameters.
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <chrono>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class Triangulation, class Points>
double time_triangulation(const Points& points) {
  const auto start = std::chrono::steady_clock::now();
  Triangulation triangulation(points.begin(), points.end());  // spatially sorted by CGAL
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return triangulation.number_of_vertices() > 0 ? seconds : 0.0;
}

std::vector<Kernel::Point_2> to_cgal(const std::vector<Point<2>>& points) {
  std::vector<Kernel::Point_2> cgal_points;
  cgal_points.reserve(points.size());
  for (const auto& p : points) cgal_points.emplace_back(p[0], p[1]);
  return cgal_points;
}

std::vector<Kernel::Point_3> to_cgal(const std::vector<Point<3>>& points) {
  std::vector<Kernel::Point_3> cgal_points;
  cgal_points.reserve(points.size());
  for (const auto& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
  return cgal_points;
}

}  // namespace

double delaunay_seconds(const std::vector<Point<2>>& points) {
  return time_triangulation<CGAL::Delaunay_triangulation_2<Kernel>>(to_cgal(points));
}

double delaunay_seconds(const std::vector<Point<3>>& points) {
  return time_triangulation<CGAL::Delaunay_triangulation_3<Kernel>>(to_cgal(points));
}

std::vector<Facet<3>> cgal_advancing_front(const std::vector<Point<3>>& points) {
  const auto cgal_points = to_cgal(points);
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::advancing_front_surface_reconstruction(cgal_points.begin(), cgal_points.end(),
                                               std::back_inserter(triangles));
  std::vector<Facet<3>> facets;
  facets.reserve(triangles.size());
  for (const auto& t : triangles)
    facets.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  return facets;
}

}  // namespace sculpt
