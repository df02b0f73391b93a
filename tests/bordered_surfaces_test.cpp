// SPDX-License-Identifier: GPL-3.0-or-later
// Bordered surfaces end where the samples end, and the automatic kind closes what is closed and
// keeps the borders that are there: generated shapes whose borders are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <string>

#include "core/spanning_openings.hpp"
#include "driver/automatic_kind.hpp"
#include "methods/robust/bordered_surface.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

Options of_kind(Surface_kind kind) {
  Options options;
  options.kind = kind;
  return options;
}

// The vertices of the border's edges.
std::set<int> border_vertices(const std::vector<Facet<3>>& triangles) {
  std::set<int> vertices;
  for (const auto& [a, b] : testing::border_edges(triangles)) vertices.insert({a, b});
  return vertices;
}

struct Bordered_shape {
  std::string example;
  std::size_t loops;
  // Whether a point lies at the true border, within about two sample spacings.
  std::function<bool(const Point<3>&)> at_border;
};

std::ostream& operator<<(std::ostream& out, const Bordered_shape& shape) {
  return out << shape.example;
}

double radius_xy(const Point<3>& p) {
  return std::hypot(p[0], p[1]);
}

const std::vector<Bordered_shape>& bordered_shapes() {
  static const std::vector<Bordered_shape> shapes = {
      {"hemisphere", 1, [](const Point<3>& p) { return p[2] < 0.1; }},
      // 40 x 40 samples over [-1, 1]^2: a step of 0.05.
      {"saddle", 1,
       [](const Point<3>& p) { return std::max(std::abs(p[0]), std::abs(p[1])) > 0.9; }},
      {"monkey-saddle", 1,
       [](const Point<3>& p) { return std::max(std::abs(p[0]), std::abs(p[1])) > 0.9; }},
      // Height 3, rows about 0.1 apart.
      {"open-cylinder", 2, [](const Point<3>& p) { return std::abs(p[2]) > 1.3; }},
      {"wavy-annulus", 2,
       [](const Point<3>& p) { return radius_xy(p) < 0.56 || radius_xy(p) > 0.96; }},
      // Holes of angular radius 0.35, 0.5, 0.7 about x, y and z; samples about 0.06 apart.
      {"holey-sphere", 3,
       [](const Point<3>& p) {
         return p[0] > std::cos(0.35 + 0.12) || p[1] > std::cos(0.5 + 0.12) ||
                p[2] > std::cos(0.7 + 0.12);
       }},
  };
  return shapes;
}

// The automatic kind keeps `kind` and gives exactly what that kind gives when asked for.
template <int D>
Reconstruction<D> expect_automatic_keeps(const std::vector<Point<D>>& samples, Surface_kind kind) {
  const auto asked = reconstruct(samples, of_kind(kind));
  auto automatic = reconstruct(samples);
  EXPECT_EQ(automatic.stats.kind, kind);
  EXPECT_TRUE(automatic.stats.kind_chosen_automatically);
  EXPECT_EQ(automatic.surface, asked.surface);
  // Stages 1-2 as the asked-for run built them (a bordered attempt takes the closed one's).
  EXPECT_EQ(automatic.stats.delaunay_cells, asked.stats.delaunay_cells);
  EXPECT_EQ(automatic.delaunay.cells, asked.delaunay.cells);
  EXPECT_EQ(automatic.sites, asked.sites);
  EXPECT_EQ(automatic.poles.poles.size(), asked.poles.poles.size());
  for (std::size_t p = 0; p < asked.poles.poles.size(); ++p) {
    EXPECT_EQ(automatic.poles.poles[p].center, asked.poles.poles[p].center);
    EXPECT_EQ(automatic.poles.poles[p].radius, asked.poles.poles[p].radius);
  }
  return automatic;
}

class Bordered_surface : public ::testing::TestWithParam<Bordered_shape> {};

TEST_P(Bordered_surface, EveryBorderIsFoundWhereTheSamplesEnd) {
  const Bordered_shape& shape = GetParam();
  const auto samples = shapes::example_points_3(shape.example);
  const auto result = reconstruct(samples, of_kind(Surface_kind::bordered));
  const Statistics& s = result.stats;
  EXPECT_EQ(s.boundary_loops, shape.loops);
  EXPECT_EQ(s.non_manifold_ridges, 0u);
  EXPECT_EQ(s.non_manifold_vertices, 0u);
  EXPECT_EQ(s.unused_samples, 0u);
  EXPECT_EQ(s.components, 1u);
  EXPECT_EQ(s.torn_loops, 0u);  // every loop is an opening
  EXPECT_TRUE(verdict(s).manifold) << verdict(s).line;
  for (int v : border_vertices(result.surface)) {
    EXPECT_TRUE(shape.at_border(samples[v]))
        << "a border vertex away from the true border: sample " << v << " at (" << samples[v][0]
        << ", " << samples[v][1] << ", " << samples[v][2] << ")";
  }
}

// The automatic kind finds the same border.
TEST_P(Bordered_surface, TheAutomaticKindKeepsTheBorders) {
  const auto automatic = expect_automatic_keeps<3>(shapes::example_points_3(GetParam().example),
                                                   Surface_kind::bordered);
  EXPECT_EQ(automatic.options.kind, Surface_kind::bordered);
  EXPECT_GT(automatic.stats.closed_spanning_facets, 0u);
  ASSERT_FALSE(automatic.stats.stages.empty());
  EXPECT_EQ(automatic.stats.stages.front().name, "closed attempt");
  // Its Delaunay triangulation and poles were the closed attempt's, not built again.
  for (const auto& stage : automatic.stats.stages) {
    EXPECT_NE(stage.name, "delaunay");
    EXPECT_NE(stage.name, "poles");
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, Bordered_surface, ::testing::ValuesIn(bordered_shapes()),
                         [](const auto& info) {
                           std::string name = info.param.example;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(Bordered_surface, TheCapOverAnOpeningIsWhatGoes) {
  // The paper's bordered rule caps most of the hemisphere's opening; the robust rule removes the
  // cap's triangles (far wider than the spacing) and its border runs all around the rim.
  const auto samples = shapes::hemisphere(3000);
  Options paper = of_kind(Surface_kind::bordered);
  paper.method = Method::paper;
  const auto capped = reconstruct(samples, paper);
  EXPECT_LT(capped.stats.boundary_ridges, 20u);
  const auto robust = reconstruct(samples, of_kind(Surface_kind::bordered));
  EXPECT_GT(robust.stats.boundary_ridges, 50u);
  EXPECT_GT(robust.stats.spanning_facets, 0u);
  EXPECT_EQ(robust.candidates.spanning.size(), robust.stats.spanning_facets);
  // The surface is made of the chosen candidates only: no triangle over the opening stays.
  const auto chosen = testing::unordered(robust.candidates.chosen);
  const auto surface = testing::unordered(robust.surface);
  for (const auto& t : surface) EXPECT_EQ(chosen.count(t), 1u);
  for (const auto& t : testing::unordered(robust.candidates.spanning)) {
    EXPECT_EQ(surface.count(t), 0u);
  }
}

// A hole 3.5 spacings wide in radius: its rim samples' own spacings reach to one side, up to
// twice the sheet's, and hid it; the median over their neighbourhoods finds it. (The kind choice
// keeps the own spacings and calls this sphere closed: an opening so narrow is not told from a
// gap in the sampling there.)
TEST(Bordered_surface, AHoleAFewSpacingsWideIsFound) {
  const double hole = 0.26;  // angular radius; the samples are 0.075 apart (sixth neighbour)
  std::vector<Point<3>> samples;
  for (const auto& p : shapes::sphere(4000)) {
    if (p[0] < std::cos(hole)) samples.push_back(p);
  }
  const auto result = reconstruct(samples, of_kind(Surface_kind::bordered));
  EXPECT_EQ(result.stats.boundary_loops, 1u);
  EXPECT_EQ(result.stats.non_manifold_ridges, 0u);
  EXPECT_EQ(result.stats.unused_samples, 0u);
  for (int v : border_vertices(result.surface)) {
    EXPECT_GT(samples[v][0], std::cos(hole + 0.15)) << "a border vertex away from the rim: " << v;
  }
}

// The neighbourhood spacing is the median of the own spacings of a sample and its 6 nearest.
TEST(Bordered_surface, NeighbourhoodSpacingIsTheMedianAroundASample) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Point<3>> samples(300);
  for (auto& p : samples) p = {unit(random), unit(random), 0.2 * unit(random)};
  const std::vector<double> own = sample_spacings<3>(samples);
  const std::vector<double> around = neighbourhood_spacings(samples);
  ASSERT_EQ(around.size(), samples.size());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    std::vector<std::pair<double, std::size_t>> by_distance;
    for (std::size_t t = 0; t < samples.size(); ++t) {
      double d2 = 0;
      for (int c = 0; c < 3; ++c)
        d2 += (samples[t][c] - samples[s][c]) * (samples[t][c] - samples[s][c]);
      by_distance.push_back({d2, t});
    }
    std::sort(by_distance.begin(), by_distance.end());
    std::vector<double> spacings;
    for (int j = 0; j < 7; ++j) spacings.push_back(own[by_distance[j].second]);
    std::sort(spacings.begin(), spacings.end());
    EXPECT_DOUBLE_EQ(around[s], spacings[3]) << "sample " << s;
  }
}

// A row of samples running out from a sheet's border, far beyond its spacing: mending attaches
// none of them by a triangle wider than the openings' growth ratio allows (before, a triangle
// whose circle's middle held other samples could reach 45 spacings out), and the surface stays
// a manifold.
TEST(Bordered_surface, SamplesFarOffTheSheetAreNotReachedFor) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Point<3>> samples;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      samples.push_back({i + jitter(random), j + jitter(random), 0.1 * jitter(random)});
    }
  }
  const int row = static_cast<int>(samples.size());
  for (int k = 1; k <= 30; ++k) {
    samples.push_back({15.3, -1.0 * k + jitter(random) / 2, 0.1 * jitter(random)});
  }
  const auto result = reconstruct(samples, of_kind(Surface_kind::bordered));
  EXPECT_EQ(result.stats.non_manifold_ridges, 0u);
  const std::vector<double> spacing = neighbourhood_spacings(samples);
  for (const auto& t : result.surface) {
    if (std::max({t[0], t[1], t[2]}) < row) continue;
    EXPECT_FALSE(spans_opening<3>(samples, spacing, t, opening_growth_ratio))
        << "a wide triangle to the row: " << t[0] << " " << t[1] << " " << t[2];
  }
}

// A scanner's sheet: random samples, spacing about 1, Gaussian noise of 2% of it across the
// sheet. Noise makes the sheet a thin slab with samples inside it and fans pinched at a vertex;
// the mending sets the samples in and joins or drops the fans (without those three steps, each of
// these sheets keeps 1 or 2 non-manifold vertices).
TEST(Bordered_surface, ANoisySheetIsABorderedManifoldThroughEverySample) {
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> along(0.0, 100.0);
    std::normal_distribution<double> noise(0.0, 0.02);
    std::vector<Point<3>> samples;
    for (int i = 0; i < 10000; ++i) {
      const double x = along(random), y = along(random);
      samples.push_back({x, y, 3 * std::sin(x / 10) * std::cos(y / 13) + noise(random)});
    }
    const auto result = reconstruct(samples, of_kind(Surface_kind::bordered));
    EXPECT_TRUE(verdict(result.stats).manifold) << verdict(result.stats).line;
    EXPECT_EQ(result.stats.unused_samples, 0u);
    EXPECT_EQ(result.stats.components, 1u);
    // Noise stands slivers on edge, and the extraction leaves small holes amid the sheet; every
    // one is a gap the least folded fill closes (greedy ear clipping left 1 or 2 of them).
    EXPECT_EQ(result.stats.boundary_loops, 1u);
    EXPECT_EQ(result.stats.torn_loops, 0u);
  }
}

// Noise tears small holes in a closed shape's bordered result where the mending finds every
// fill folded back; they are told from openings (Statistics::torn_loops), and the automatic kind
// keeps the shape closed.
TEST(Bordered_surface, HolesNoiseTearsAreTornLoopsNotOpenings) {
  // 10,000 samples, noise of 5% and 10% of the spacing: 2 and 10 loops torn.
  for (double noise : {0.05, 0.1}) {
    SCOPED_TRACE(noise);
    const auto samples = shapes::noisy_sphere(10000, noise);
    const auto bordered = reconstruct(samples, of_kind(Surface_kind::bordered));
    EXPECT_GT(bordered.stats.boundary_loops, 0u);
    EXPECT_EQ(bordered.stats.torn_loops, bordered.stats.boundary_loops);
    EXPECT_EQ(reconstruct(samples).stats.kind, Surface_kind::closed);
  }
}

// A wide circle is an opening only where its middle is empty: on a flat sheet of samples 0.1
// apart, three nearly collinear samples of a row (a sliver, circumradius 1.25) have samples
// around their circle's middle; an ear of three rim samples of a round hole of radius 0.5 cut
// out of the same sheet has the hole's centre as its middle.
TEST(Bordered_surface, AWideCircleWhoseMiddleIsOnTheSheetBridgesNoOpening) {
  std::vector<Point<3>> sheet;
  for (int i = -15; i <= 15; ++i) {
    for (int j = -15; j <= 15; ++j) sheet.push_back({0.1 * i, 0.1 * j, 0});
  }
  sheet[sheet.size() / 2][1] = 0.004;  // the middle sample of row j = 0, just off the row
  const std::size_t middle = sheet.size() / 2, left = middle - 31, right = middle + 31;
  ASSERT_EQ(sheet[left][0], -0.1);
  ASSERT_EQ(sheet[right][0], 0.1);
  const Point_tree<3> sheet_tree(sheet.data(), sheet.data() + sheet.size());
  const Facet<3> sliver = {int(left), int(middle), int(right)};
  EXPECT_GT(facet_circumradius<3>(sheet, sliver), 1.0);
  EXPECT_TRUE(circle_middle_on_the_sheet(sheet, sheet_tree, sliver));

  std::vector<Point<3>> holed;
  for (const auto& p : sheet) {
    if (std::hypot(p[0], p[1]) > 0.55) holed.push_back(p);
  }
  const int rim = static_cast<int>(holed.size());
  for (int k = 0; k < 3; ++k) {
    const double angle = 0.2 * k;
    holed.push_back({0.5 * std::cos(angle), 0.5 * std::sin(angle), 0});
  }
  const Point_tree<3> holed_tree(holed.data(), holed.data() + holed.size());
  const Facet<3> ear = {rim, rim + 1, rim + 2};
  EXPECT_NEAR(facet_circumradius<3>(holed, ear), 0.5, 1e-12);
  EXPECT_FALSE(circle_middle_on_the_sheet(holed, holed_tree, ear));
}

// A fill need not be Delaunay: across a slot (an elliptic hole 2 long and 0.8 wide in a sheet of
// samples 0.1 apart), the triangle of the rim samples at 0°, 9° and 180° has its circle's middle
// near the rim, so the circle test would let it bridge the slot; its body covers the slot's
// empty middle. Triangles on the sheet, and the sliver along a row, cover no empty disc.
TEST(Bordered_surface, AFillAcrossASlotCoversAnEmptyDisc) {
  std::vector<Point<3>> samples;
  const auto in_slot = [](double x, double y) { return x * x + (y / 0.4) * (y / 0.4) <= 1.15; };
  for (int i = -20; i <= 20; ++i) {
    for (int j = -20; j <= 20; ++j) {
      if (!in_slot(0.1 * i, 0.1 * j)) samples.push_back({0.1 * i, 0.1 * j, 0});
    }
  }
  const int rim = static_cast<int>(samples.size());
  for (int k = 0; k < 40; ++k) {
    const double angle = 2 * M_PI * k / 40;
    samples.push_back({std::cos(angle), 0.4 * std::sin(angle), 0});
  }
  const Point_tree<3> tree(samples.data(), samples.data() + samples.size());
  const std::vector<double> spacing = neighbourhood_spacings(samples, tree);
  const Facet<3> across = {rim, rim + 1, rim + 20};
  EXPECT_TRUE(circle_middle_on_the_sheet(samples, tree, across));
  EXPECT_TRUE(covers_an_empty_disc(samples, tree, spacing, across, opening_growth_ratio));
  // Three neighbouring rim samples, and a triangle of the sheet beside the slot.
  EXPECT_FALSE(covers_an_empty_disc(samples, tree, spacing, {rim + 5, rim + 6, rim + 7},
                                    opening_growth_ratio));
  EXPECT_FALSE(covers_an_empty_disc(samples, tree, spacing, {0, 1, 41}, opening_growth_ratio));
  // A sliver along a row of the sheet: three neighbours on the edge x = -2, the middle one lifted.
  std::vector<Point<3>> lifted = samples;
  lifted[20][2] = 0.004;
  const Point_tree<3> lifted_tree(lifted.data(), lifted.data() + lifted.size());
  const Facet<3> sliver = {19, 20, 21};
  EXPECT_GT(facet_circumradius<3>(lifted, sliver), 2 * spacing[20]);
  EXPECT_FALSE(covers_an_empty_disc(lifted, lifted_tree, spacing, sliver, opening_growth_ratio));
}

// count_spanning measures only the spacings that can matter; it counts what measuring them all
// counts, on closed results with openings capped (many spanning facets) and without (none).
template <int D>
void expect_spanning_count_of_all_spacings(const std::vector<Point<D>>& samples) {
  const auto closed = reconstruct(samples, of_kind(Surface_kind::closed));
  const std::vector<Point<D>> sites(closed.sites.begin(),
                                    closed.sites.begin() + closed.sample_count());
  const std::vector<double> spacing = sample_spacings<D>(sites);
  const Point_tree<D> tree(sites.data(), sites.data() + sites.size());
  std::size_t expected = 0;
  for (const auto& facet : closed.surface) {
    bool spans = spans_opening<D>(sites, spacing, facet);
    if constexpr (D == 3) spans = spans && !circle_middle_on_the_sheet(sites, tree, facet);
    expected += spans;
  }
  EXPECT_EQ(count_spanning<D>(sites, closed.surface), expected);
}

TEST(Automatic_kind, CountingSpanningFacetsSkipsOnlySpacingsThatCannotMatter) {
  for (const char* name : {"hemisphere", "holey-sphere", "open-cylinder", "torus", "bumpy"}) {
    SCOPED_TRACE(name);
    expect_spanning_count_of_all_spacings<3>(shapes::example_points_3(name));
  }
  for (const char* name : {"arc", "spiral", "circle"}) {
    SCOPED_TRACE(name);
    expect_spanning_count_of_all_spacings<2>(shapes::example_points_2(name));
  }
}

// Closed shapes: the automatic kind gives exactly the closed result.
TEST(Automatic_kind, ClosedSurfacesStayClosed) {
  for (const char* name : {"sphere", "torus", "bumpy", "torso", "bumpy-nonuniform"}) {
    SCOPED_TRACE(name);
    const auto automatic =
        expect_automatic_keeps<3>(shapes::example_points_3(name), Surface_kind::closed);
    EXPECT_EQ(automatic.stats.closed_spanning_facets, 0u);
    EXPECT_EQ(automatic.stats.stages.back().name, "kind choice");
  }
}

// Samples on a tilted plane (rounding keeps them off it by a hair, so the Delaunay
// triangulation has cells, all flat): the closed attempt bounds no solid and has no surface; the
// bordered one is the sheet, kept (it once kept the empty closed result).
TEST(Automatic_kind, AFlatSheetIsBorderedNotAnEmptyClosedSurface) {
  std::mt19937 random(11);
  const auto unit = [&] { return random() / 4294967296.0; };
  std::vector<Point<3>> sheet;
  for (int i = 0; i < 300; ++i) {
    const double x = unit(), y = unit();
    sheet.push_back({x, y, 0.3 * x + 0.7 * y + 1});
  }
  Options closed;
  closed.kind = Surface_kind::closed;
  ASSERT_TRUE(reconstruct(sheet, closed).surface.empty());
  const auto automatic = expect_automatic_keeps<3>(sheet, Surface_kind::bordered);
  EXPECT_FALSE(automatic.surface.empty());
  EXPECT_EQ(automatic.stats.unused_samples, 0u);
  EXPECT_EQ(automatic.stats.boundary_loops, 1u);
}

TEST(Automatic_kind, ClosedCurvesStayClosedAndOpenOnesOpen) {
  for (const char* name : {"circle", "star", "blob", "nested", "nonuniform"}) {
    SCOPED_TRACE(name);
    expect_automatic_keeps<2>(shapes::example_points_2(name), Surface_kind::closed);
  }
  for (const char* name : {"arc", "wavy-arc", "spiral", "strokes"}) {
    SCOPED_TRACE(name);
    const auto automatic =
        expect_automatic_keeps<2>(shapes::example_points_2(name), Surface_kind::bordered);
    EXPECT_EQ(automatic.stats.non_manifold_ridges, 0u) << "no branch point";
    EXPECT_EQ(automatic.stats.unused_samples, 0u);
  }
}

// The other methods take the automatic kind as closed and run once: the co-cone (no bordered
// rule) and the paper's method (as published, told its kind).
TEST(Automatic_kind, OnlyTheRobustMethodChooses) {
  for (Method method : {Method::cocone, Method::paper}) {
    SCOPED_TRACE(to_string(method));
    const auto result = reconstruct(shapes::hemisphere(1500), testing::with_method(method));
    Options closed = testing::with_method(method);
    closed.kind = Surface_kind::closed;
    EXPECT_EQ(result.surface, reconstruct(shapes::hemisphere(1500), closed).surface);
    EXPECT_EQ(result.stats.kind, Surface_kind::closed);
    EXPECT_FALSE(result.stats.kind_chosen_automatically);
    for (const auto& stage : result.stats.stages) {
      EXPECT_NE(stage.name, "closed attempt");
      EXPECT_NE(stage.name, "kind choice");
    }
  }
}

// The automatic kind's last word: a bordered result is kept when it has an opening (a border
// loop not torn), the closed result has the facets over openings to have capped them (2 each on
// a surface, 1 on a curve), and it has fewer defects than the closed one with those facets
// counted, and no more than the closed one's and one per torn loop.
TEST(Automatic_kind, BorderLoopsAreOpeningsOnlyWhereTheClosedResultCappedThem) {
  Statistics closed, bordered;
  // As a torus with noise of 5% of its spacing: 7 facets over openings, every loop torn.
  bordered.boundary_loops = 4;
  bordered.torn_loops = 4;
  EXPECT_FALSE(keeps_bordered<3>(closed, 7, bordered));
  // One loop an opening: kept.
  bordered.torn_loops = 3;
  EXPECT_TRUE(keeps_bordered<3>(closed, 7, bordered));
  bordered.torn_loops = 0;
  bordered.boundary_loops = 5;
  EXPECT_FALSE(keeps_bordered<3>(closed, 9, bordered));
  EXPECT_TRUE(keeps_bordered<3>(closed, 10, bordered));
  bordered.boundary_loops = 0;
  EXPECT_FALSE(keeps_bordered<3>(closed, 100, bordered));
  // A curve's gap is bridged by one edge.
  bordered.boundary_loops = 2;
  EXPECT_TRUE(keeps_bordered<2>(closed, 2, bordered));
  EXPECT_FALSE(keeps_bordered<3>(closed, 2, bordered));
  // More defects than the closed result's, with its facets over openings counted as defects.
  bordered.boundary_loops = 32;
  bordered.torn_loops = 30;
  bordered.non_manifold_vertices = 30;
  closed.unused_samples = 5;
  EXPECT_FALSE(keeps_bordered<3>(closed, 25, bordered));
  EXPECT_TRUE(keeps_bordered<3>(closed, 26, bordered));
  // More defects than the closed result's and the torn loops explain, however many facets over
  // openings: a 2-manifold is not traded for a surface that is not (a CAD mesh's flat faces).
  closed.unused_samples = 0;
  bordered.non_manifold_vertices = 31;
  EXPECT_FALSE(keeps_bordered<3>(closed, 1000, bordered));
  bordered.non_manifold_vertices = 30;
  bordered.unused_samples = 1;
  EXPECT_FALSE(keeps_bordered<3>(closed, 1000, bordered));
  bordered.unused_samples = 0;
  EXPECT_TRUE(keeps_bordered<3>(closed, 1000, bordered));
  // A surface with defects in more pieces than the closed one: each piece more is a defect (a
  // shape torn apart, as CGAL's camel bordered: 5 pieces against 1).
  closed.components = 1;
  bordered.components = 2;
  EXPECT_FALSE(keeps_bordered<3>(closed, 1000, bordered));  // 30 + 1 > 30 torn loops
  bordered.torn_loops = 31;
  bordered.boundary_loops = 33;
  EXPECT_TRUE(keeps_bordered<3>(closed, 1000, bordered));
  // Without defects, more pieces are sheets of their own (the closed attempt joined them); a
  // curve's separate strokes likewise.
  bordered.non_manifold_vertices = 0;
  bordered.torn_loops = 0;
  bordered.components = 5;
  EXPECT_TRUE(keeps_bordered<3>(closed, 1000, bordered));
  bordered.non_manifold_vertices = 2;
  bordered.torn_loops = 2;
  EXPECT_TRUE(keeps_bordered<2>(closed, 1000, bordered));
  EXPECT_FALSE(keeps_bordered<3>(closed, 1000, bordered));
}

// A border loop through fewer samples than the rim of the smallest opening the kind choice finds
// is no opening either (a hole the bordered rule cut): as a scan of a closed part, smoothed,
// whose bordered result has 5 loops, 4 torn and one short, with a pinched vertex beside each.
TEST(Automatic_kind, ShortBorderLoopsAreNotOpenings) {
  Statistics closed, bordered;
  closed.components = bordered.components = 1;
  bordered.boundary_loops = 5;
  bordered.torn_loops = 4;
  bordered.non_manifold_vertices = 4;
  EXPECT_TRUE(keeps_bordered<3>(closed, 5, bordered));  // the one not torn is an opening
  bordered.short_loops = 1;
  EXPECT_FALSE(keeps_bordered<3>(closed, 5, bordered));
  EXPECT_FALSE(keeps_bordered<3>(closed, 1000, bordered));
  // A long loop beside them is an opening.
  bordered.boundary_loops = 6;
  EXPECT_TRUE(keeps_bordered<3>(closed, 5, bordered));
}

// A handle a bordered result with defects has beyond the closed one's is a defect: the closed
// result's are decided by evidence, the bordered rule's are not (a scan of CGAL's spool, smoothed:
// bordered with 25 loops, 22 torn, 18 pinched vertices and χ -119, against a closed result of
// genus 0). Only the handles certain count: each pinched vertex may read one too many.
TEST(Automatic_kind, HandlesTheBorderedRuleAddsAreDefects) {
  Statistics closed, bordered;
  closed.components = bordered.components = 1;
  closed.euler_characteristic = 2;  // a sphere
  // An annulus whose two rims touch at a vertex: one border piece, V - E + F = -1, no handle.
  bordered.boundary_loops = 1;
  bordered.non_manifold_vertices = 1;
  bordered.euler_characteristic = -1;
  EXPECT_EQ(certain_handles(bordered), 0u);
  // Three loops, two torn, two pinched vertices.
  bordered.boundary_loops = 3;
  bordered.torn_loops = 2;
  bordered.non_manifold_vertices = 2;
  bordered.euler_characteristic = -5;  // the pinches may explain it all
  EXPECT_EQ(certain_handles(bordered), 0u);
  EXPECT_TRUE(keeps_bordered<3>(closed, 100, bordered));
  bordered.euler_characteristic = -7;  // one handle for certain: 3 defects, against 2 torn loops
  EXPECT_EQ(certain_handles(bordered), 1u);
  EXPECT_FALSE(keeps_bordered<3>(closed, 100, bordered));
  closed.euler_characteristic = 0;  // unless the closed result has as many (a torus)
  EXPECT_TRUE(keeps_bordered<3>(closed, 100, bordered));
  closed.euler_characteristic = 2;
  // Curves have no handles: a 2D result's loops are strokes.
  EXPECT_TRUE(keeps_bordered<2>(closed, 100, bordered));
  // A clean bordered surface keeps its handles (one the closed carving refused may be real).
  bordered.non_manifold_vertices = 0;
  bordered.torn_loops = 0;
  bordered.boundary_loops = 1;
  bordered.euler_characteristic = -3;  // a sheet with two handles
  EXPECT_EQ(certain_handles(bordered), 2u);
  EXPECT_TRUE(keeps_bordered<3>(closed, 100, bordered));
}

}  // namespace
}  // namespace sculpt
