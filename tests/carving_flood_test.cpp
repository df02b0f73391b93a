// SPDX-License-Identifier: GPL-3.0-or-later
// The robust carving's shortcut (methods/robust/manifold_carving.hpp): the outer cells flooded
// at once stand for carving them cell by cell only where that is where the carving was going;
// elsewhere the flood is undone and leaves no trace. And the check of a closed skin it relies on.
#include <gtest/gtest.h>

#include <vector>

#include "core/closed_skin_check.hpp"
#include "core/facet_topology.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

template <int D>
void expect_flood_and_carving_agree(const std::vector<Point<D>>& samples, bool flood_stands) {
  Options flood;
  flood.kind = Surface_kind::closed;
  Options cell_by_cell = flood;
  cell_by_cell.carve_by_flood = false;
  const auto flooded = reconstruct(samples, flood);
  const auto carved = reconstruct(samples, cell_by_cell);
  EXPECT_EQ(flooded.stats.carved_by_flood, flood_stands);
  EXPECT_FALSE(carved.stats.carved_by_flood);
  EXPECT_EQ(flooded.surface, carved.surface);
  EXPECT_EQ(flooded.solid, carved.solid);
  EXPECT_EQ(flooded.stats.carved_cells, carved.stats.carved_cells);
  // A flood that stood fills the topology from its check; the carving's is measured.
  EXPECT_EQ(flooded.stats.facets, carved.stats.facets);
  EXPECT_EQ(flooded.stats.components, carved.stats.components);
  EXPECT_EQ(flooded.stats.euler_characteristic, carved.stats.euler_characteristic);
  EXPECT_EQ(flooded.stats.boundary_ridges, carved.stats.boundary_ridges);
  EXPECT_EQ(flooded.stats.boundary_loops, carved.stats.boundary_loops);
  EXPECT_EQ(flooded.stats.non_manifold_ridges, carved.stats.non_manifold_ridges);
  EXPECT_EQ(flooded.stats.non_manifold_vertices, carved.stats.non_manifold_vertices);
  EXPECT_EQ(flooded.stats.unused_samples, carved.stats.unused_samples);
  if (!flood_stands) {  // undone without a trace: the carving's very events and cells kept
    ASSERT_EQ(flooded.carving.events.size(), carved.carving.events.size());
    for (std::size_t i = 0; i < carved.carving.events.size(); ++i) {
      EXPECT_EQ(flooded.carving.events[i].cell, carved.carving.events[i].cell);
    }
    EXPECT_EQ(flooded.carving.kept_outer_cells, carved.carving.kept_outer_cells);
  }
}

TEST(Carving_flood, StandsForTheCarvingOnCleanShapes) {
  {
    SCOPED_TRACE("torus");
    expect_flood_and_carving_agree<3>(shapes::torus(4000), true);
  }
  {
    SCOPED_TRACE("torus knot");
    expect_flood_and_carving_agree<3>(shapes::example_points_3("torus-knot"), true);
  }
  {
    SCOPED_TRACE("bumpy sphere");
    expect_flood_and_carving_agree<3>(shapes::bumpy_sphere(3000), true);
  }
  {
    SCOPED_TRACE("star (2D)");
    expect_flood_and_carving_agree<2>(shapes::example_points_2("star"), true);
  }
}

// Noise makes the carving keep a few outer cells (removing them would leave a sample off or
// pinch the surface); an annulus has a cavity the flood cannot reach.
// Two small spheres far apart: the flood gives two pieces of 150 samples, fewer than a group
// removal may cut off without evidence; each holds its samples' inner poles (a part of its own,
// piece_evidence.hpp), so the flood stands, and the carving would have separated them too.
TEST(Carving_flood, StandsForSmallPiecesThatArePartsOfTheirOwn) {
  auto samples = shapes::sphere(150);
  for (const auto& p : shapes::sphere(150)) samples.push_back({p[0] + 5, p[1], p[2]});
  expect_flood_and_carving_agree<3>(samples, true);
  const auto result = reconstruct(samples, Options{});
  EXPECT_EQ(result.stats.components, 2u);
  EXPECT_EQ(result.stats.euler_characteristic, 4);
}

TEST(Carving_flood, IsUndoneWhereTheCarvingKeepsCellsOrOpensCavities) {
  {
    SCOPED_TRACE("noisy sphere");
    expect_flood_and_carving_agree<3>(shapes::noisy_sphere(10000, 0.1), false);
  }
  {
    SCOPED_TRACE("annulus (2D)");
    expect_flood_and_carving_agree<2>(shapes::example_points_2("nested"), false);
  }
}

// The boundary of the tetrahedron 0123, facing out.
std::vector<Facet<3>> tetrahedron(int a, int b, int c, int d) {
  return {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}};
}

TEST(Closed_skin_check, ATetrahedronsBoundaryIsClosed) {
  const Skin_check check = check_closed_skin<3>(4, tetrahedron(0, 1, 2, 3));
  EXPECT_TRUE(check.closed_manifold_through_all);
  EXPECT_EQ(check.pieces, 1u);
  EXPECT_EQ(check.smallest_piece, 4u);
}

// The topology a passed check implies is the one measure_topology measures.
template <int D>
void expect_topology_as_measured(std::size_t samples, const std::vector<Facet<D>>& facets) {
  const Skin_check check = check_closed_skin<D>(samples, facets);
  ASSERT_TRUE(check.closed_manifold_through_all);
  Statistics implied;
  closed_skin_topology<D>(samples, facets.size(), check, implied);
  Statistics measured;
  measure_topology_by_ridges<D>(samples, facets, measured);
  EXPECT_EQ(implied.facets, measured.facets);
  EXPECT_EQ(implied.unused_samples, measured.unused_samples);
  EXPECT_EQ(implied.components, measured.components);
  EXPECT_EQ(implied.boundary_ridges, measured.boundary_ridges);
  EXPECT_EQ(implied.non_manifold_ridges, measured.non_manifold_ridges);
  EXPECT_EQ(implied.non_manifold_vertices, measured.non_manifold_vertices);
  EXPECT_EQ(implied.boundary_loops, measured.boundary_loops);
  EXPECT_EQ(implied.euler_characteristic, measured.euler_characteristic);
}

TEST(Closed_skin_check, CountsPiecesAndTheSmallest) {
  auto facets = tetrahedron(0, 1, 2, 3);
  const auto octahedron = std::vector<Facet<3>>{{4, 6, 8}, {4, 8, 7}, {4, 7, 9}, {4, 9, 6},
                                                {5, 8, 6}, {5, 7, 8}, {5, 9, 7}, {5, 6, 9}};
  facets.insert(facets.end(), octahedron.begin(), octahedron.end());
  const Skin_check check = check_closed_skin<3>(10, facets);
  EXPECT_TRUE(check.closed_manifold_through_all);
  EXPECT_EQ(check.pieces, 2u);
  EXPECT_EQ(check.smallest_piece, 4u);
  expect_topology_as_measured<3>(10, facets);
}

TEST(Closed_skin_check, RefusesOpenPinchedFlippedOrIncompleteSkins) {
  auto open = tetrahedron(0, 1, 2, 3);
  open.pop_back();
  EXPECT_FALSE(check_closed_skin<3>(4, open).closed_manifold_through_all);

  auto flipped = tetrahedron(0, 1, 2, 3);
  std::swap(flipped[3][0], flipped[3][1]);
  EXPECT_FALSE(check_closed_skin<3>(4, flipped).closed_manifold_through_all);

  // Two tetrahedra touching at vertex 0: a closed surface, but not a manifold there.
  auto pinched = tetrahedron(0, 1, 2, 3);
  const auto other = tetrahedron(0, 4, 5, 6);
  pinched.insert(pinched.end(), other.begin(), other.end());
  EXPECT_FALSE(check_closed_skin<3>(7, pinched).closed_manifold_through_all);

  // A sample on no facet; a facet with a repeated vertex; a box corner.
  EXPECT_FALSE(check_closed_skin<3>(5, tetrahedron(0, 1, 2, 3)).closed_manifold_through_all);
  auto degenerate = tetrahedron(0, 1, 2, 3);
  degenerate.push_back({0, 0, 1});
  EXPECT_FALSE(check_closed_skin<3>(4, degenerate).closed_manifold_through_all);
  EXPECT_FALSE(check_closed_skin<3>(3, tetrahedron(0, 1, 2, 3)).closed_manifold_through_all);
}

TEST(Closed_skin_check, CurvesEnterAndLeaveEachSampleOnce) {
  const std::vector<Facet<2>> square = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  EXPECT_TRUE(check_closed_skin<2>(4, square).closed_manifold_through_all);
  const std::vector<Facet<2>> figure_eight = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}};
  EXPECT_FALSE(check_closed_skin<2>(5, figure_eight).closed_manifold_through_all);
  const std::vector<Facet<2>> open_path = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_FALSE(check_closed_skin<2>(4, open_path).closed_manifold_through_all);
  const std::vector<Facet<2>> two_triangles = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}};
  const Skin_check two = check_closed_skin<2>(6, two_triangles);
  EXPECT_TRUE(two.closed_manifold_through_all);
  EXPECT_EQ(two.pieces, 2u);
  EXPECT_EQ(two.smallest_piece, 3u);
  expect_topology_as_measured<2>(6, two_triangles);
  const std::vector<Facet<2>> loop_at_a_sample = {{0, 0}};
  EXPECT_FALSE(check_closed_skin<2>(1, loop_at_a_sample).closed_manifold_through_all);
}

}  // namespace
}  // namespace sculpt
