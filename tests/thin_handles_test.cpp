// SPDX-License-Identifier: GPL-3.0-or-later
// Handles thinner than the samples' spacing (core/thin_handles.hpp): a torus whose tube is three
// or four samples around is one thin handle, found once however many of its rings qualify; a
// tube of eight around, or a fat tube of three, is not; a loop around a small disc (the link of a
// vertex of three triangles) is no handle; the verdict says how many are suspect.
#include "core/thin_handles.hpp"

#include <cmath>

#include "core/facet_topology.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

struct Mesh {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles;
};

// A torus of `ring` segments along its core circle (radius 1) and `tube` around its tube (radius
// `tube_radius`), each quad split in two, oriented outward.
Mesh torus(int ring, int tube, double tube_radius) {
  Mesh mesh;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < ring; ++i) {
    for (int j = 0; j < tube; ++j) {
      const double theta = 2 * pi * i / ring, phi = 2 * pi * j / tube;
      const double r = 1 + tube_radius * std::cos(phi);
      mesh.points.push_back(
          {r * std::cos(theta), r * std::sin(theta), tube_radius * std::sin(phi)});
    }
  }
  const auto at = [&](int i, int j) { return ((i + ring) % ring) * tube + (j + tube) % tube; };
  for (int i = 0; i < ring; ++i) {
    for (int j = 0; j < tube; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

Statistics topology_of(const Mesh& mesh) {
  return facet_topology(mesh.points.size(), mesh.triangles);
}

TEST(ThinHandles, ATubeThreeSamplesAroundIsOneThinHandle) {
  // 40 segments along a core of length 2 pi: about 0.16 apart; three around a tube of radius 0.09
  // are 0.16 apart too.
  const Mesh mesh = torus(40, 3, 0.09);
  const Statistics stats = topology_of(mesh);
  ASSERT_EQ(stats.euler_characteristic, 0);
  // Asked for up to five, it finds one: every other ring depends on the first (cut along two
  // rings, the tube falls in two).
  const auto handles = find_thin_handles(mesh.points, mesh.triangles, 5);
  ASSERT_EQ(handles.size(), 1u);
  EXPECT_EQ(handles[0].loop[3], -1);
  EXPECT_LE(handles[0].width_over_spacing, thin_neck);
}

TEST(ThinHandles, ATubeFourSamplesAroundIsOneToo) {
  const auto handles =
      find_thin_handles(torus(40, 4, 0.11).points, torus(40, 4, 0.11).triangles, 1);
  ASSERT_EQ(handles.size(), 1u);
  EXPECT_GE(handles[0].loop[3], 0);
}

TEST(ThinHandles, AWellSampledTubeOrAFatOneIsNot) {
  const Mesh round = torus(40, 8, 0.2);
  EXPECT_TRUE(find_thin_handles(round.points, round.triangles, 1).empty());
  // Three around, but the tube is wide and the samples along it close: the loop is five times
  // their spacing, a real handle the sampling shows (coarsely).
  const Mesh fat = torus(120, 3, 0.5);
  EXPECT_TRUE(find_thin_handles(fat.points, fat.triangles, 1).empty());
}

TEST(ThinHandles, ALoopAroundASmallDiscIsNoHandle) {
  // An octahedron with one face split at its centre: the split's three triangles are bounded by
  // a loop of three that is no face, and bounds a disc.
  Mesh mesh;
  mesh.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  mesh.points.push_back({0.4, 0.4, 0.4});
  mesh.triangles[0] = {0, 2, 6};
  mesh.triangles.push_back({2, 4, 6});
  mesh.triangles.push_back({4, 0, 6});
  ASSERT_EQ(topology_of(mesh).euler_characteristic, 2);
  EXPECT_TRUE(find_thin_handles(mesh.points, mesh.triangles, 3).empty());
}

TEST(ThinHandles, TrianglesOrientedEveryWhichWayAreNotSearched) {
  Mesh mesh = torus(40, 3, 0.09);
  std::swap(mesh.triangles[7][0], mesh.triangles[7][1]);  // one triangle turned over
  EXPECT_TRUE(find_thin_handles(mesh.points, mesh.triangles, 1).empty());
}

TEST(ThinHandles, AResultCarriesThemAndItsVerdictSaysSo) {
  const Mesh mesh = torus(40, 3, 0.09);
  Reconstruction<3> result;
  result.sites = mesh.points;
  result.surface = mesh.triangles;
  result.stats = topology_of(mesh);
  find_thin_handles_of(result);
  EXPECT_EQ(result.stats.thin_handles, 1u);
  ASSERT_EQ(result.thin_handles.size(), 1u);
  const std::string line = verdict(result.stats).line;
  EXPECT_NE(line.find("of genus 1"), std::string::npos) << line;
  EXPECT_NE(line.find("1 handle suspect"), std::string::npos) << line;

  // A surface with a border is not asked.
  result.surface.pop_back();
  result.stats = topology_of({mesh.points, result.surface});
  find_thin_handles_of(result);
  EXPECT_EQ(result.stats.thin_handles, 0u);
  EXPECT_TRUE(result.thin_handles.empty());
}

TEST(ThinHandles, AWellSampledTorusReconstructedHasNone) {
  const auto result = reconstruct(shapes::torus(3000), Options{});
  ASSERT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
  ASSERT_EQ(result.stats.euler_characteristic, 0);
  EXPECT_EQ(result.stats.thin_handles, 0u);
}

}  // namespace
}  // namespace sculpt
