// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's solid and surface read off DT(S ∪ BBV) by circumball queries (what the command
// line runs) are the ones inserting OUP gives (what the viewer shows), triangle for triangle,
// including inputs full of cospherical points, where only CGAL's symbolic perturbation decides.
// And DT(S ∪ BBV ∪ P) rebuilt from every site (the robust method) is the one inserting P into
// DT(S ∪ BBV) gives (the paper's method), cell for cell. And stage 1's insertion, step by step,
// is CGAL's range insertion, in CGAL's order.
#include <algorithm>
#include <vector>

#include "core/delaunay.hpp"
#include "core2d/traits_2.hpp"
#include "core3d/traits_3.hpp"
#include "methods/paper/pole_insertion.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

// Cells as sorted vertex lists; facets rotated to start at their least vertex (orientation kept).
template <int D>
std::vector<Cell<D>> canonical_cells(std::vector<Cell<D>> cells) {
  for (auto& c : cells) std::sort(c.begin(), c.end());
  std::sort(cells.begin(), cells.end());
  return cells;
}

template <int D>
std::vector<Facet<D>> canonical_facets(std::vector<Facet<D>> facets) {
  for (auto& f : facets) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(facets.begin(), facets.end());
  return facets;
}

template <int D>
void expect_queries_match_insertion(const std::vector<Point<D>>& samples) {
  Options options;
  options.method = Method::paper;
  options.kind = Surface_kind::closed;
  options.keep_triangulations = true;  // builds DT(S ∪ OUP) by insertion
  const auto inserted = reconstruct(samples, options);
  options.keep_triangulations = false;  // answers with queries on DT(S ∪ BBV)
  const auto queried = reconstruct(samples, options);

  ASSERT_GT(inserted.sculpted_delaunay.cell_count, 0u);
  EXPECT_EQ(queried.sculpted_delaunay.cell_count, 0u) << "the command line must not insert";
  EXPECT_EQ(queried.insertion.inserted_poles, inserted.insertion.inserted_poles);
  EXPECT_FALSE(inserted.solid.empty());
  EXPECT_EQ(canonical_cells<D>(queried.solid), canonical_cells<D>(inserted.solid));
  EXPECT_EQ(canonical_facets<D>(queried.surface), canonical_facets<D>(inserted.surface));
  EXPECT_EQ(queried.stats.euler_characteristic, inserted.stats.euler_characteristic);
}

// Integer points on the boundary of a cube (3D) or square (2D): many cospherical (cocircular)
// and coplanar subsets.
std::vector<Point<3>> cube_lattice(int side) {
  std::vector<Point<3>> points;
  for (int x = 0; x <= side; ++x)
    for (int y = 0; y <= side; ++y)
      for (int z = 0; z <= side; ++z) {
        const bool on_boundary = x == 0 || y == 0 || z == 0 || x == side || y == side || z == side;
        if (on_boundary) points.push_back({double(x), double(y), double(z)});
      }
  return points;
}

std::vector<Point<2>> square_lattice(int side) {
  std::vector<Point<2>> points;
  for (int x = 0; x <= side; ++x)
    for (int y = 0; y <= side; ++y)
      if (x == 0 || y == 0 || x == side || y == side) points.push_back({double(x), double(y)});
  return points;
}

// Integer points on two nested spheres, x² + y² + z² = 49 and 50: many samples on each sphere,
// so many cells of the first triangulation share their circumsphere.
std::vector<Point<3>> lattice_sphere() {
  std::vector<Point<3>> points;
  for (int x = -7; x <= 7; ++x)
    for (int y = -7; y <= 7; ++y)
      for (int z = -7; z <= 7; ++z)
        if (x * x + y * y + z * z == 49 || x * x + y * y + z * z == 50)
          points.push_back({double(x), double(y), double(z)});
  return points;
}

// Random points of a coarse integer grid: degenerate in every way at once (cospherical and
// coplanar subsets, poles on other cells' circumspheres).
template <int D>
std::vector<Point<D>> coarse_grid_points(int count, int side, unsigned seed) {
  std::vector<Point<D>> points;
  unsigned state = seed;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<int>((state >> 8) % static_cast<unsigned>(side));
  };
  while (static_cast<int>(points.size()) < count) {
    Point<D> p;
    for (int k = 0; k < D; ++k) p[k] = next();
    if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
  }
  return points;
}

TEST(SculptedSolid, QueriesMatchInsertionOnCoarseGrids) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE(seed);
    expect_queries_match_insertion<3>(coarse_grid_points<3>(60, 5, seed));
    expect_queries_match_insertion<2>(coarse_grid_points<2>(30, 7, seed));
  }
}

TEST(SculptedSolid, QueriesMatchInsertionOnSmoothSurfaces) {
  expect_queries_match_insertion<3>(shapes::sphere(600));
  expect_queries_match_insertion<3>(shapes::torus(2500));
  expect_queries_match_insertion<3>(shapes::bumpy_sphere(1500));
}

TEST(SculptedSolid, QueriesMatchInsertionWhereThePaperFails) {
  // Thin strands, a genus-3 shape and a one-sided undersampling: mislabelled poles, dangling
  // facets and non-manifold skins, which must still agree cell for cell.
  expect_queries_match_insertion<3>(shapes::torus_knot_tube(2500));
  expect_queries_match_insertion<3>(shapes::three_holes(3000));
  expect_queries_match_insertion<3>(shapes::thinned_on_one_side(shapes::torus(4000), 6));
}

TEST(SculptedSolid, QueriesMatchInsertionOnCosphericalPoints) {
  expect_queries_match_insertion<3>(cube_lattice(8));
  expect_queries_match_insertion<3>(lattice_sphere());
  expect_queries_match_insertion<2>(square_lattice(12));
}

// The paper's bordered run inserts every labelled pole into DT(S ∪ BBV) and keeps the cells;
// the same sites triangulated anew (Sculpted_by::rebuilding, from a triangulation of the samples
// and corners, which it clears) must give the same cells. Compared by their corners' positions:
// poles at one point (cospherical cells have one circumcentre) are one vertex, numbered as the
// last of them inserted, which differs between the two orders.
template <class Traits>
void expect_rebuilding_matches_insertion(const std::vector<Point<Traits::dimension>>& samples) {
  constexpr int D = Traits::dimension;
  Options options;
  options.method = Method::paper;
  options.kind = Surface_kind::bordered;
  options.keep_triangulations = true;
  const auto inserted = reconstruct(samples, options);
  ASSERT_GT(inserted.insertion.inserted_poles.size(), 0u);
  auto rebuilt_result = inserted;
  rebuilt_result.sculpted_delaunay = {};
  Statistics unused;
  const Stage_clock clock(unused, options);
  typename Traits::Triangulation rebuilt;
  const std::vector<Point<D>> first_sites(inserted.sites.begin(),
                                          inserted.sites.begin() + first_inserted_site(inserted));
  insert_in_spatial_order<Traits>(rebuilt, first_sites, 0, clock);
  insert_poles<Traits>(rebuilt, rebuilt_result, clock, Sculpted_by::rebuilding);
  const Delaunay_stage<D>& cells = rebuilt_result.sculpted_delaunay;
  ASSERT_EQ(cells.cell_count, inserted.sculpted_delaunay.cell_count);
  const auto by_position = [&](const std::vector<Cell<D>>& numbered) {
    std::vector<std::array<Point<D>, D + 1>> corners;
    for (const auto& cell : numbered) {
      std::array<Point<D>, D + 1> c;
      for (int i = 0; i <= D; ++i) c[i] = inserted.sites[cell[i]];
      std::sort(c.begin(), c.end());
      corners.push_back(c);
    }
    std::sort(corners.begin(), corners.end());
    return corners;
  };
  EXPECT_EQ(by_position(cells.cells), by_position(inserted.sculpted_delaunay.cells));
}

TEST(SculptedSolid, RebuildingGivesTheTriangulationInsertionGives) {
  expect_rebuilding_matches_insertion<Traits_3>(cube_lattice(6));
  expect_rebuilding_matches_insertion<Traits_3>(lattice_sphere());
  expect_rebuilding_matches_insertion<Traits_3>(shapes::hemisphere(1500));
  expect_rebuilding_matches_insertion<Traits_2>(square_lattice(12));
  for (unsigned seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    expect_rebuilding_matches_insertion<Traits_3>(coarse_grid_points<3>(60, 5, seed));
    expect_rebuilding_matches_insertion<Traits_2>(coarse_grid_points<2>(30, 7, seed));
  }
}

// Stage 1 inserts step by step (for its progress) what CGAL's range insertion inserts at once,
// in the same order: the vertices, in the triangulation's own order, are the same points.
template <class Traits, class Plain>
void expect_cgal_insertion_order(const std::vector<Point<Traits::dimension>>& sites) {
  const testing::Silent_clock silent;
  const Stage_clock& clock = silent.clock;
  typename Traits::Triangulation stepwise;
  insert_in_spatial_order<Traits>(stepwise, sites, 0, clock);
  std::vector<typename Traits::Cgal_point> points;
  for (const auto& site : sites) points.push_back(Traits::to_cgal(site));
  const Plain at_once(points.begin(), points.end());
  std::vector<typename Traits::Cgal_point> ours, cgals;
  for (auto v : stepwise.finite_vertex_handles()) {
    ours.push_back(v->point());
    EXPECT_EQ(Traits::to_cgal(sites[v->info()]), v->point()) << "a vertex knows its site";
  }
  for (auto v : at_once.finite_vertex_handles()) cgals.push_back(v->point());
  ASSERT_EQ(ours.size(), sites.size());
  EXPECT_EQ(ours, cgals);
}

TEST(SculptedSolid, TheDelaunayStageInsertsInCgalsOrder) {
  expect_cgal_insertion_order<Traits_3, CGAL::Delaunay_triangulation_3<Traits_3::Kernel>>(
      shapes::hemisphere(3000));
  expect_cgal_insertion_order<Traits_3, CGAL::Delaunay_triangulation_3<Traits_3::Kernel>>(
      cube_lattice(6));
  expect_cgal_insertion_order<Traits_2, CGAL::Delaunay_triangulation_2<Traits_2::Kernel>>(
      shapes::star(200).samples);
}

// The crusts insert the samples and the Voronoi vertices (or poles) into a triangulation of their
// own, vertices with infos and cells without, by the same stepwise insertion: it must give what
// CGAL's range insertion with infos gives, repeated points included (the Voronoi vertices of a
// lattice repeat: two triangles of each square share a circumcentre). Vertices with their
// indices and cells as their vertices' indices, in order.
template <class Traits, class Crust>
void expect_crust_insertion_order(const std::vector<Point<Traits::dimension>>& samples) {
  constexpr int D = Traits::dimension;
  typename Traits::Triangulation first;
  for (const auto& s : samples) Traits::insert_near(first, Traits::to_cgal(s), {});
  std::vector<Point<D>> sites = samples;
  for (auto cell : Traits::finite_cells(first)) {
    sites.push_back(Traits::from_cgal(Traits::circumcenter(first, cell)));
  }
  const testing::Silent_clock silent;
  const Stage_clock& clock = silent.clock;
  Crust stepwise;
  insert_in_spatial_order<Traits>(stepwise, sites, 0, clock);
  std::vector<std::pair<typename Traits::Cgal_point, int>> pairs;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    pairs.push_back({Traits::to_cgal(sites[i]), static_cast<int>(i)});
  }
  const Crust at_once(pairs.begin(), pairs.end());
  const auto described = [](const Crust& t) {
    std::vector<std::pair<typename Traits::Cgal_point, int>> vertices;
    for (auto v : t.finite_vertex_handles()) vertices.push_back({v->point(), v->info()});
    return std::make_pair(vertices, testing::cells_as_vertex_infos<D>(t));
  };
  EXPECT_EQ(described(stepwise), described(at_once));
  EXPECT_LT(stepwise.number_of_vertices(), sites.size()) << "repeated points are one vertex";
}

TEST(SculptedSolid, TheCrustsTriangulationsInsertInCgalsOrder) {
  using Kernel = Traits_3::Kernel;
  expect_crust_insertion_order<
      Traits_3, CGAL::Delaunay_triangulation_3<
                    Kernel, CGAL::Triangulation_data_structure_3<
                                CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>>>>(
      cube_lattice(6));
  expect_crust_insertion_order<
      Traits_2, CGAL::Delaunay_triangulation_2<
                    Traits_2::Kernel,
                    CGAL::Triangulation_data_structure_2<
                        CGAL::Triangulation_vertex_base_with_info_2<int, Traits_2::Kernel>>>>(
      square_lattice(12));
}

TEST(SculptedSolid, QueriesMatchInsertionOnCurves) {
  expect_queries_match_insertion<2>(shapes::star(60).samples);
  expect_queries_match_insertion<2>(shapes::star(35).samples);
  expect_queries_match_insertion<2>(shapes::nested_circles(60, 30).samples);
  expect_queries_match_insertion<2>(shapes::nonuniform_ellipse(80).samples);
}

}  // namespace
}  // namespace sculpt
