// SPDX-License-Identifier: GPL-3.0-or-later
// The methods CGAL computes for us, beside ours on the same stages: the Advancing Front keeps
// its promise (a closed manifold on smooth dense samples, never a non-manifold edge), and the
// alpha shape takes the smallest alpha that makes one solid holding every sample (the alpha
// CGAL's own search finds); the command line skips the shared stages neither reads.
#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "methods/cgal/optimal_alpha.hpp"
#include "scene/scene.hpp"
#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

TEST(CgalMethods, TheAdvancingFrontClosesSmoothShapesOrientedOutward) {
  for (const auto& [name, samples] : std::vector<std::pair<const char*, std::vector<Point<3>>>>{
           {"sphere", shapes::sphere(2000)}, {"torus", shapes::torus(4000)}}) {
    SCOPED_TRACE(name);
    const auto result = reconstruct(samples, testing::with_method(Method::advancing_front));
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
    EXPECT_TRUE(testing::consistently_oriented_closed(result.surface));
    // Outward: the sphere's normals point away from its centre.
    if (std::string(name) == "sphere") {
      for (const auto& t : result.surface) {
        const auto &a = result.sites[t[0]], &b = result.sites[t[1]], &c = result.sites[t[2]];
        const double nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        const double ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
        const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        ASSERT_GT(nx * a[0] + ny * a[1] + nz * a[2], 0);
      }
    }
  }
}

TEST(CgalMethods, TheAlphaShapeIsOneSolidHoldingEverySample) {
  const auto samples = shapes::torso(8000);
  const auto result = reconstruct(samples, testing::with_method(Method::alpha_shape));
  EXPECT_GT(result.stats.alpha, 0);
  EXPECT_EQ(result.stats.components, 1u);
  ASSERT_FALSE(result.solid.empty());
  EXPECT_EQ(result.stats.solid_cells, result.solid.size());
  // Every sample is a vertex of the solid (on its surface or inside it).
  std::set<int> in_solid;
  for (const auto& cell : result.solid) in_solid.insert(cell.begin(), cell.end());
  EXPECT_EQ(in_solid.size(), samples.size());
  // The surface is the solid's boundary: each of its triangles is a face of exactly one cell.
  auto faces = testing::faces_of(result.solid);
  for (auto t : result.surface) {
    std::sort(t.begin(), t.end());
    EXPECT_EQ(faces[t], 1);
  }
  // Alpha is a length of the input: eight times larger points, eight times larger alpha.
  auto scaled = samples;
  for (auto& p : scaled) {
    for (double& x : p) x *= 8;
  }
  EXPECT_NEAR(reconstruct(scaled, testing::with_method(Method::alpha_shape)).stats.alpha,
              8 * result.stats.alpha, 1e-9 * result.stats.alpha);
  testing::expect_every_stage_builds(result);
}

// CGAL's structures list simplices in an order that follows memory addresses; the results are
// put in one order (each simplex from its smallest vertex, orientation kept; the list sorted), so
// that a run writes the same bytes whatever ran before it in the process.
TEST(CgalMethods, TheirTrianglesAndCellsComeInOneOrder) {
  const auto samples = shapes::torus(3000);
  for (const Method method : {Method::alpha_shape, Method::advancing_front}) {
    SCOPED_TRACE(to_string(method));
    Options options = testing::with_method(method);
    options.keep_solid = true;
    const auto first = reconstruct(samples, options);
    ASSERT_FALSE(first.surface.empty());
    EXPECT_TRUE(std::is_sorted(first.surface.begin(), first.surface.end()));
    for (const auto& t : first.surface) ASSERT_TRUE(t[0] < t[1] && t[0] < t[2]);
    EXPECT_TRUE(std::is_sorted(first.solid.begin(), first.solid.end()));
    for (const auto& c : first.solid) ASSERT_TRUE(c[0] < c[1] && c[0] < c[2] && c[0] < c[3]);
    if (method == Method::advancing_front) {
      EXPECT_TRUE(testing::consistently_oriented_closed(first.surface)) << "orientation kept";
    }
    // Other work in between (other allocations), then the same points: the same lists.
    reconstruct(shapes::sphere(5000), testing::with_method(Method::alpha_shape));
    const auto again = reconstruct(samples, options);
    EXPECT_EQ(again.surface, first.surface);
    EXPECT_EQ(again.solid, first.solid);
  }
}

TEST(CgalMethods, TheAlphaShapeTakesTheRadiusItIsGiven) {
  const auto samples = shapes::torso(8000);
  Options options = testing::with_method(Method::alpha_shape);
  const auto chosen = reconstruct(samples, options);
  // Given back the radius it chose, in the input's units, it makes the same solid.
  options.alpha = chosen.stats.alpha;
  const auto same = reconstruct(samples, options);
  EXPECT_NEAR(same.stats.alpha, chosen.stats.alpha, 1e-9 * chosen.stats.alpha);
  EXPECT_EQ(same.stats.solid_cells, chosen.stats.solid_cells);
  // Smaller, it holds fewer cells and leaves samples off its surface; larger than the shape,
  // it is the convex hull: more cells than any other, a sphere's topology.
  options.alpha = 0.5 * chosen.stats.alpha;
  const auto smaller = reconstruct(samples, options);
  EXPECT_LT(smaller.stats.solid_cells, chosen.stats.solid_cells);
  EXPECT_GT(smaller.stats.unused_samples, chosen.stats.unused_samples);
  options.alpha = 1e3;
  const auto hull = reconstruct(samples, options);
  EXPECT_GT(hull.stats.solid_cells, chosen.stats.solid_cells);
  EXPECT_EQ(hull.stats.components, 1u);
  EXPECT_EQ(hull.stats.euler_characteristic, 2);
  EXPECT_NEAR(hull.stats.alpha, 1e3, 1e-9);
  options.alpha = -1;
  EXPECT_THROW(reconstruct(samples, options), Input_error);
}

// One sweep finds the alpha CGAL's binary search finds, for one piece and for more, on shapes
// and on a random cloud (where the count of pieces goes up and down as alpha grows).
TEST(CgalMethods, TheOptimalAlphaIsTheOneCgalsSearchFinds) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Cell_base = CGAL::Alpha_shape_cell_base_3<
      Kernel, CGAL::Triangulation_cell_base_with_info_3<
                  int, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>;
  using Tds =
      CGAL::Triangulation_data_structure_3<CGAL::Alpha_shape_vertex_base_3<Kernel>, Cell_base>;
  using Alpha_shape = CGAL::Alpha_shape_3<CGAL::Delaunay_triangulation_3<Kernel, Tds>>;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point<3>> cloud(3000);
  for (auto& p : cloud) p = {unit(random), unit(random), unit(random)};
  for (const auto& [name, points] : std::vector<std::pair<const char*, std::vector<Point<3>>>>{
           {"torso", shapes::torso(3000)}, {"torus", shapes::torus(2000)}, {"cloud", cloud}}) {
    std::vector<Kernel::Point_3> cgal_points;
    for (const auto& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
    Alpha_shape shape(cgal_points.begin(), cgal_points.end(), 0, Alpha_shape::REGULARIZED);
    for (std::size_t pieces : {1u, 2u, 5u}) {
      SCOPED_TRACE(std::string(name) + ", pieces " + std::to_string(pieces));
      const auto cgal = shape.find_optimal_alpha(pieces);
      const auto ours = optimal_alpha_index(shape, pieces);
      ASSERT_EQ(ours.has_value(), cgal != shape.alpha_end());
      if (ours) {
        EXPECT_EQ(*ours, static_cast<std::size_t>(cgal - shape.alpha_begin()));
      }
    }
  }
}

// Neither the Advancing Front nor the alpha shape reads DT(S ∪ BBV) or the poles: a run that
// keeps no triangulation (the command line) builds neither and gets the same surface (the alpha
// shape's exactly; the Advancing Front breaks ties by memory address, so on this clean sphere
// the same closed manifold through every sample), and still refuses a repeated point (which the
// skipped triangulation would have found).
TEST(CgalMethods, TheCommandLineSkipsTheSharedStagesTheyDoNotRead) {
  const auto samples = shapes::sphere(1500);
  const auto as_set = [](std::vector<Facet<3>> facets) {
    for (auto& f : facets) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    std::sort(facets.begin(), facets.end());
    return facets;
  };
  for (Method method : {Method::advancing_front, Method::alpha_shape}) {
    SCOPED_TRACE(to_string(method));
    Options options = testing::with_method(method);
    const auto viewer = reconstruct(samples, options);
    EXPECT_GT(viewer.stats.delaunay_cells, 0u);
    EXPECT_GT(viewer.stats.poles, 0u);
    options.keep_triangulations = false;
    const auto command_line = reconstruct(samples, options);
    EXPECT_EQ(command_line.stats.delaunay_cells, 0u);
    for (const auto& stage : command_line.stats.stages) {
      EXPECT_NE(stage.name, "delaunay");
      EXPECT_NE(stage.name, "poles");
    }
    EXPECT_EQ(command_line.sample_count(), samples.size());
    if (method == Method::alpha_shape) {
      EXPECT_EQ(as_set(command_line.surface), as_set(viewer.surface));
    } else {
      for (const auto* run : {&viewer, &command_line}) {
        EXPECT_TRUE(verdict(run->stats).manifold) << verdict(run->stats).line;
        EXPECT_EQ(run->stats.unused_samples, 0u);
        EXPECT_EQ(run->surface.size(), 2 * samples.size() - 4);  // a sphere's, closed
      }
    }
    auto repeated = samples;
    repeated.push_back(samples[17]);
    EXPECT_THROW(reconstruct(repeated, options), Duplicate_points);
  }
}

TEST(CgalMethods, BothReconstructSurfacesOnly) {
  for (Method method : {Method::advancing_front, Method::alpha_shape}) {
    EXPECT_FALSE(reconstructs_in(method, 2));
    EXPECT_THROW(reconstruct(shapes::circle(64).samples, testing::with_method(method)),
                 Input_error);
  }
}

}  // namespace
}  // namespace sculpt
