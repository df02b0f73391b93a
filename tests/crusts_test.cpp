// SPDX-License-Identifier: GPL-3.0-or-later
// The crusts, siblings of the sculpting methods over the same first stages: the crust of Amenta,
// Bern and Kamvysselis and the NN-crust of Dey and Kumar give the polygon through consecutive
// samples on closed curves sampled densely enough, keep their own stage as data, and refuse
// surfaces.
#include <gtest/gtest.h>

#include <set>

#include "scene/scene.hpp"
#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

TEST(Crusts, ExactOnDenselySampledClosedCurves) {
  for (Method method : {Method::crust, Method::nn_crust}) {
    for (const auto& [name, truth] : std::vector<std::pair<const char*, shapes::Sampled_curve>>{
             {"circle", shapes::circle(64)},
             {"star", shapes::star(200)},
             {"blob", shapes::blob(150)},
             {"nested circles", shapes::nested_circles(120, 60)},
             {"non-uniform ellipse", shapes::nonuniform_ellipse(200)}}) {
      SCOPED_TRACE(std::string(to_string(method)) + " on " + name);
      const auto result = reconstruct(truth.samples, testing::with_method(method));
      EXPECT_EQ(testing::undirected(result.surface), testing::undirected(truth.edges));
      EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
      EXPECT_EQ(result.stats.method, method);
    }
  }
}

TEST(Crusts, TheCrustKeepsItsVoronoiVerticesAndItsTriangulation) {
  Options options = testing::with_method(Method::crust);
  options.keep_triangulations = true;
  const auto truth = shapes::blob(150);
  const auto result = reconstruct(truth.samples, options);
  const auto& crust = result.crust;
  EXPECT_EQ(crust.voronoi_vertices.size(), result.delaunay.cell_count);
  ASSERT_EQ(crust.delaunay.cells.size(), crust.delaunay.cell_count);
  const int n = static_cast<int>(truth.samples.size());
  std::set<std::pair<int, int>> sample_edges;
  for (const auto& cell : crust.delaunay.cells) {
    for (int i = 0; i < 3; ++i) {
      const int a = cell[i], b = cell[(i + 1) % 3];
      ASSERT_LT(a, n + static_cast<int>(crust.voronoi_vertices.size()));
      if (a < n && b < n) sample_edges.insert(std::minmax(a, b));
    }
  }
  // The curve is exactly the triangulation's edges between two samples.
  EXPECT_EQ(sample_edges, testing::undirected(result.surface));
  // And its stages build as scenes; the stages of sculpting are not the crust's.
  testing::expect_every_stage_builds(result);
  scene::Request propagation;
  propagation.stage = scene::Stage::propagation;
  try {
    scene::build_scene(result, propagation);
    ADD_FAILURE() << "the crust has no propagation stage";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("crust-delaunay"), std::string::npos) << e.what();
  }
}

TEST(Crusts, TheNnCrustHasNoEndsWhereTheRobustRuleKeepsThem) {
  // Two strokes side by side: the NN-crust joins each end to the other stroke (it assumes closed
  // curves); the robust method's bordered rule, which starts from the same edges, ends them.
  const auto strokes = shapes::two_strokes();
  const auto nn = reconstruct(strokes.samples, testing::with_method(Method::nn_crust));
  EXPECT_NE(testing::undirected(nn.surface), testing::undirected(strokes.edges));
  Options robust = testing::with_method(Method::robust);
  robust.kind = Surface_kind::bordered;
  const auto bordered = reconstruct(strokes.samples, robust);
  EXPECT_EQ(testing::undirected(bordered.surface), testing::undirected(strokes.edges));
}

TEST(Crusts, TheNnCrustRefusesSurfacesWithOneLine) {
  EXPECT_FALSE(reconstructs_in(Method::nn_crust, 3));
  EXPECT_TRUE(reconstructs_in(Method::crust, 3));  // tests/surface_filtering_test.cpp
  try {
    reconstruct(shapes::sphere(200), testing::with_method(Method::nn_crust));
    ADD_FAILURE() << "the NN-crust reconstructed a surface";
  } catch (const Input_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("curves (2D points) only"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace sculpt
