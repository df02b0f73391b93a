// SPDX-License-Identifier: GPL-3.0-or-later
// The methods that filter Delaunay triangles and extract a manifold from them: the crust for
// surfaces (Amenta, Bern & Kamvysselis) and the co-cone (Amenta, Choi, Dey & Leekha). Their
// papers promise a closed manifold through every sample on well-sampled smooth closed surfaces;
// the extraction's two steps are checked on small hand-made cases where the answer is known.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "frontend/pseudo_code.hpp"
#include "methods/cocone/cocone_method.hpp"
#include "methods/extraction/edge_map.hpp"
#include "methods/extraction/manifold_extraction.hpp"
#include "scene/scene.hpp"
#include "scene_support.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

using testing::unordered;

// An octahedron about the origin: its 8 faces, 6 vertices.
const std::vector<Point<3>> octahedron_vertices = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const std::vector<Facet<3>> octahedron_faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

// The edge map answers, for every edge of a set of triangles, which triangles have it (in
// increasing order, either way round), and nothing for an edge no triangle has; checked against
// a count made the slow way on a fan of many triangles about one edge and the octahedron.
TEST(ManifoldExtraction, TheEdgeMapKnowsTheTrianglesOfEveryEdge) {
  std::vector<Facet<3>> triangles = octahedron_faces;
  for (int k = 0; k < 40; ++k) triangles.push_back({100, 101, 200 + k});  // 40 on one edge
  const extraction_detail::Edge_map edges(triangles);
  std::map<std::pair<int, int>, std::vector<int>> expected;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int j = 0; j < 3; ++j) {
      const int a = triangles[t][j], b = triangles[t][(j + 1) % 3];
      expected[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  }
  EXPECT_EQ(edges.edge_count(), expected.size());
  std::set<int> numbers;
  for (const auto& [edge, on] : expected) {
    const auto [a, b] = edge;
    const auto found = edges.on(b, a);
    EXPECT_EQ(std::vector<int>(found.begin(), found.end()), on);
    EXPECT_EQ(edges.index(a, b), edges.index(b, a));
    numbers.insert(edges.index(a, b));
  }
  EXPECT_EQ(numbers.size(), expected.size());  // one number per edge, 0 .. count - 1
  EXPECT_EQ(*numbers.begin(), 0);
  EXPECT_EQ(*numbers.rbegin(), static_cast<int>(expected.size()) - 1);
  EXPECT_EQ(edges.on(0, 1).size(), 0u);  // opposite vertices of the octahedron
  EXPECT_EQ(edges.index(0, 1), -1);
  EXPECT_EQ(edges.on(100, 101).size(), 40u);
}

TEST(ManifoldExtraction, TheWalkKeepsTheOuterBoundaryAndLeavesTheInside) {
  // The octahedron's faces and, inside it, the square through its equator's four vertices
  // (two triangles): the walk turns outwards at every edge, so the square is left out.
  std::vector<Facet<3>> triangles = octahedron_faces;
  triangles.push_back({0, 2, 1});
  triangles.push_back({0, 1, 3});
  const auto surface = walk_outer_boundary(octahedron_vertices, triangles);
  EXPECT_EQ(unordered(surface), unordered(octahedron_faces));
  EXPECT_TRUE(testing::consistently_oriented_closed(surface));
  // Oriented outwards: each face's normal points away from the centre.
  for (const auto& t : surface) {
    const auto& a = octahedron_vertices[t[0]];
    const auto normal =
        extraction_detail::cross(extraction_detail::minus(octahedron_vertices[t[1]], a),
                                 extraction_detail::minus(octahedron_vertices[t[2]], a));
    EXPECT_GT(extraction_detail::dot(normal, {a[0], a[1], a[2]}), 0);
  }
}

TEST(ManifoldExtraction, ACavityIsWalkedFacingIntoIt) {
  // A hollow octahedron: the outer faces and, inside, a smaller octahedron, the cavity's wall.
  // Both are kept; the outer faces point away from the centre, the inner ones towards it (out
  // of the solid, into the cavity). A second octahedron beside the first faces away from its
  // own centre.
  std::vector<Point<3>> points = octahedron_vertices;
  for (const auto& p : octahedron_vertices) points.push_back({0.4 * p[0], 0.4 * p[1], 0.4 * p[2]});
  for (const auto& p : octahedron_vertices) points.push_back({p[0] + 5, p[1], p[2]});
  std::vector<Facet<3>> triangles;
  for (int copy = 0; copy < 3; ++copy) {
    for (auto t : octahedron_faces)
      triangles.push_back({t[0] + 6 * copy, t[1] + 6 * copy, t[2] + 6 * copy});
  }
  const auto surface = walk_outer_boundary(points, triangles);
  ASSERT_EQ(surface.size(), 24u);
  EXPECT_TRUE(testing::consistently_oriented_closed(surface));
  for (const auto& t : surface) {
    const auto& a = points[t[0]];
    const auto normal = extraction_detail::cross(extraction_detail::minus(points[t[1]], a),
                                                 extraction_detail::minus(points[t[2]], a));
    const bool beside = t[0] >= 12, cavity = t[0] >= 6 && t[0] < 12;
    const Point<3> centre{beside ? 5.0 : 0.0, 0, 0};
    const double outward = extraction_detail::dot(normal, extraction_detail::minus(a, centre));
    if (cavity) {
      EXPECT_LT(outward, 0) << "a face of the cavity";
    } else {
      EXPECT_GT(outward, 0);
    }
  }
}

TEST(ManifoldExtraction, PruningRemovesFinsAndSharpFoldsButNotASheetOrItsHoles) {
  std::vector<Point<3>> points = octahedron_vertices;
  points.push_back({2, 0.1, 0});  // 6: a fin out of vertex 0
  std::vector<Facet<3>> triangles = octahedron_faces;
  triangles.push_back({0, 6, 4});  // its edges 0-6 and 6-4 have no other triangle
  const auto pruned = prune_sharp_edges(points, triangles, Rims::pruned);
  EXPECT_EQ(unordered(pruned), unordered({{0, 6, 4}}));
  EXPECT_EQ(unordered(triangles), unordered(octahedron_faces));

  // The octahedron's faces meet at 109.5 degrees; a regular tetrahedron's at 70.5, sharper
  // than 90: a closed surface cannot fold so sharply where it is well sampled, so all go.
  std::vector<Facet<3>> closed = octahedron_faces;
  EXPECT_TRUE(prune_sharp_edges(octahedron_vertices, closed, Rims::pruned).empty());
  // A hole eats the surface ring by ring, unless the rims are kept; prune_candidates keeps
  // them when it must.
  std::vector<Facet<3>> holed(octahedron_faces.begin() + 1, octahedron_faces.end());
  auto eaten = holed;
  EXPECT_EQ(prune_sharp_edges(octahedron_vertices, eaten, Rims::pruned).size(), 7u);
  Rims rims = Rims::pruned;
  EXPECT_TRUE(prune_candidates(octahedron_vertices, holed, rims).empty());
  EXPECT_EQ(rims, Rims::kept);
  EXPECT_EQ(holed.size(), 7u);
  // Still, a fin goes when rims are kept.
  std::vector<Facet<3>> with_fin = octahedron_faces;
  with_fin.push_back({0, 6, 4});
  EXPECT_EQ(prune_sharp_edges(points, with_fin, Rims::kept).size(), 1u);
  const std::vector<Point<3>> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::vector<Facet<3>> faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  EXPECT_EQ(prune_sharp_edges(tetrahedron, faces, Rims::pruned).size(), 4u);
  EXPECT_TRUE(faces.empty());
}

TEST(Cocone, ASegmentMeetsTheCoconeUnlessBothEndsLieInOneCone) {
  const Point<3> p{0, 0, 0};
  const std::array<double, 3> up{0, 0, 1};
  // Both ends far along +v: the segment stays in the cone about the pole vector.
  EXPECT_FALSE(segment_meets_cocone(p, up, {0.1, 0, 1}, {-0.1, 0.1, 2}));
  // From above to below the tangent plane: it crosses the co-cone.
  EXPECT_TRUE(segment_meets_cocone(p, up, {0.1, 0, 1}, {0.1, 0, -1}));
  // One end within 22.5 degrees of the tangent plane.
  EXPECT_TRUE(segment_meets_cocone(p, up, {1, 0, 0.3}, {0, 0, 1}));
  EXPECT_FALSE(segment_meets_cocone(p, up, {1, 0, 0.5}, {0, 0, 1}));
}

// The built-in closed shapes the papers' promise covers: smooth and densely sampled.
std::vector<std::pair<const char*, std::vector<Point<3>>>> smooth_closed_shapes() {
  return {{"sphere", shapes::sphere(2000)},
          {"torus", shapes::torus(4000)},
          {"bumpy sphere", shapes::bumpy_sphere(6000)},
          {"torso", shapes::torso(8000)},
          {"torus knot", shapes::example_points_3("torus-knot")},
          {"three holes", shapes::example_points_3("three-holes")}};
}

TEST(SurfaceFiltering, CrustAndCoconeCloseTheSmoothBuiltInShapes) {
  for (Method method : {Method::crust, Method::cocone}) {
    for (const auto& [name, samples] : smooth_closed_shapes()) {
      SCOPED_TRACE(std::string(to_string(method)) + " on the " + name);
      const auto result = reconstruct(samples, testing::with_method(method));
      const Verdict v = verdict(result.stats);
      EXPECT_TRUE(v.manifold) << v.line;
      EXPECT_EQ(result.stats.unused_samples, 0u);
      EXPECT_EQ(result.stats.boundary_ridges, 0u);
      EXPECT_TRUE(testing::consistently_oriented_closed(result.surface));
    }
  }
}

TEST(SurfaceFiltering, TheCandidatesAreKeptAsAStageAndDrawn) {
  const auto result = reconstruct(shapes::sphere(2000), testing::with_method(Method::cocone));
  ASSERT_FALSE(result.candidates.chosen.empty());
  // The surface is made of candidates, none of them pruned.
  const auto chosen = unordered(result.candidates.chosen);
  const auto pruned = unordered(result.candidates.pruned);
  for (const auto& t : unordered(result.surface)) {
    EXPECT_TRUE(chosen.count(t));
    EXPECT_FALSE(pruned.count(t));
  }
  testing::expect_every_stage_builds(result);
  scene::Request candidates;
  candidates.stage = scene::Stage::candidates;
  const auto ids = scene::layer_ids(scene::build_scene(result, candidates));
  EXPECT_NE(std::find(ids.begin(), ids.end(), "candidates"), ids.end());
  // The co-cone has no triangulation of its own: the crust's stage is not its.
  scene::Request crust;
  crust.stage = scene::Stage::crust_delaunay;
  EXPECT_THROW(scene::build_scene(result, crust), std::invalid_argument);
}

TEST(SurfaceFiltering, TheSurfaceCrustTriangulatesTheSamplesWithTheirPoles) {
  const auto samples = shapes::sphere(2000);
  const auto result = reconstruct(samples, testing::with_method(Method::crust));
  EXPECT_EQ(result.crust.voronoi_vertices.size(), result.stats.poles);
  ASSERT_EQ(result.crust.delaunay.cells.size(), result.crust.delaunay.cell_count);
  // Every candidate is a triangle of DT(S ∪ P) between three samples.
  std::set<std::array<int, 3>> faces_between_samples;
  const int n = static_cast<int>(samples.size());
  for (const auto& cell : result.crust.delaunay.cells) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face;
      for (int j = 0, k = 0; j < 4; ++j) {
        if (j != skip) face[k++] = cell[j];
      }
      std::sort(face.begin(), face.end());
      if (face[2] < n) faces_between_samples.insert(face);
    }
  }
  for (const auto& t : unordered(result.candidates.chosen)) {
    EXPECT_TRUE(faces_between_samples.count(t));
  }
  EXPECT_EQ(scene::stages_of(Method::crust, 3).size(), 7u);
}

TEST(SurfaceFiltering, TheCoconeRefusesCurvesInOneLine) {
  try {
    reconstruct(shapes::circle(64).samples, testing::with_method(Method::cocone));
    ADD_FAILURE() << "the co-cone reconstructs surfaces only";
  } catch (const Input_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("surfaces (3D points) only"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

// Every stage a method has points at a line of that method's pseudo-code (the viewer highlights
// it), in both dimensions.
TEST(SurfaceFiltering, EveryStageOfEveryMethodHasItsLineOfPseudoCode) {
  for (int dimension : {2, 3}) {
    for (Method method : testing::methods_in(dimension)) {
      const std::string name = to_string(method);
      const auto& code = frontend::pseudo_code(method, Surface_kind::closed, dimension);
      for (scene::Stage stage : scene::stages_of(method, dimension)) {
        if (stage == scene::Stage::propagation) continue;  // its line follows the events
        SCOPED_TRACE(std::string(name) + " " + std::to_string(dimension) + "D " +
                     scene::stage_id(stage));
        ASSERT_TRUE(code.lines_of_stage.count(stage));
        for (int line : code.lines_of_stage.at(stage))
          EXPECT_LT(line, static_cast<int>(code.lines.size()));
      }
    }
  }
}

}  // namespace
}  // namespace sculpt
