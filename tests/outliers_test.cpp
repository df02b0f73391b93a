// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0's outlier removal (core/outlying_samples.hpp, driver/cleaning.hpp): a scanner's stray
// returns are removed before the method, where asked or with the noise of noisy samples, and the
// surface no longer reaches out to them; samples of a surface are never taken for outliers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "core/outlying_samples.hpp"
#include "shapes/portable_random.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

constexpr double major_radius = 1.0, minor_radius = 0.4;

// Where a point lies off the torus of shapes::torus: its distance from the tube's surface, and
// the unit normal there.
double off_torus(const Point<3>& p, Point<3>* normal = nullptr) {
  const double ring = std::hypot(p[0], p[1]);
  const Point<3> centre{major_radius * p[0] / ring, major_radius * p[1] / ring, 0};
  const double from_centre = std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
  if (normal) {
    for (int k = 0; k < 3; ++k) (*normal)[k] = (p[k] - centre[k]) / from_centre;
  }
  return std::abs(from_centre - minor_radius);
}

struct Torus_with_outliers {
  std::vector<Point<3>> samples;  // the torus's first, then the outliers
  std::size_t on_torus = 0;
  double spacing = 0;
};

// 4,000 samples of the torus and `strays` outliers, each off a sample along the normal by 4 to 9
// times the spacing, outwards (the tube is only 6 spacings round: a stray inside it is
// surrounded by the wall, and the inward ones are the noisy sphere's below).
Torus_with_outliers torus_with_outliers(int strays) {
  Torus_with_outliers t;
  t.samples = shapes::torus(4000, major_radius, minor_radius);
  t.on_torus = t.samples.size();
  const double area = 4 * M_PI * M_PI * major_radius * minor_radius;
  t.spacing = std::sqrt(area / double(t.on_torus));
  shapes::Portable_random random(5);
  for (int i = 0; i < strays; ++i) {
    const Point<3>& base = t.samples[std::size_t(i) * 97 % t.on_torus];
    Point<3> normal;
    off_torus(base, &normal);
    const double height = (4 + 5 * random.unit()) * t.spacing;
    t.samples.push_back(
        {base[0] + height * normal[0], base[1] + height * normal[1], base[2] + height * normal[2]});
  }
  return t;
}

// The farthest a triangle's centroid lies off the torus, in spacings.
double reach_off_torus(const Reconstruction<3>& r, double spacing) {
  double farthest = 0;
  for (const auto& t : r.surface) {
    Point<3> centroid{0, 0, 0};
    for (int v : t) {
      for (int k = 0; k < 3; ++k) centroid[k] += r.sites[v][k] / 3;
    }
    farthest = std::max(farthest, off_torus(centroid) / spacing);
  }
  return farthest;
}

TEST(Outliers, StrayReturnsAreRemovedAndTheSurfaceNoLongerReachesThem) {
  const Torus_with_outliers t = torus_with_outliers(40);
  Options as_given;
  as_given.cleaning = Cleaning::none;
  const auto spiky = reconstruct(t.samples, as_given);
  EXPECT_GT(reach_off_torus(spiky, t.spacing), 2) << "the outliers no longer make spikes";

  Options asked;
  asked.cleaning = Cleaning::outliers;
  const auto cleaned = reconstruct(t.samples, asked);
  std::vector<int> strays(t.samples.size() - t.on_torus);
  std::iota(strays.begin(), strays.end(), static_cast<int>(t.on_torus));
  EXPECT_EQ(cleaned.removed_outliers, strays) << "every stray, and no sample of the torus";
  EXPECT_EQ(cleaned.given_samples, t.samples);
  ASSERT_EQ(cleaned.sample_count(), t.on_torus);
  EXPECT_TRUE(
      std::equal(cleaned.sites.begin(), cleaned.sites.begin() + t.on_torus, t.samples.begin()))
      << "removing is not smoothing: the samples kept are as given";
  EXPECT_TRUE(cleaned.stats.cleaned);
  EXPECT_FALSE(cleaned.stats.smoothed);
  EXPECT_EQ(cleaned.stats.outliers_removed, strays.size());
  EXPECT_EQ(cleaned.stats.euler_characteristic, 0);
  EXPECT_EQ(cleaned.stats.unused_samples, 0u);
  EXPECT_LT(reach_off_torus(cleaned, t.spacing), 0.5);
  const std::string line = verdict(cleaned.stats).line;
  EXPECT_TRUE(verdict(cleaned.stats).manifold) << line;
  EXPECT_NE(line.find("cleaned first (40 outliers removed, not on it)"), std::string::npos) << line;
  EXPECT_EQ(cleaned.stats.stages.front().name, "cleaning");
}

TEST(Outliers, AClusterOfStraysIsFoundInRounds) {
  // Four returns side by side, five spacings off: each has the other three among its nearest.
  Torus_with_outliers t = torus_with_outliers(0);
  Point<3> normal;
  const Point<3> base = t.samples[123];
  off_torus(base, &normal);
  for (int i = 0; i < 4; ++i) {
    const double height = (5 + 0.1 * i) * t.spacing, aside = 0.1 * t.spacing * (i % 2);
    t.samples.push_back({base[0] + height * normal[0] + aside, base[1] + height * normal[1],
                         base[2] + height * normal[2] + 0.1 * t.spacing * (i / 2)});
  }
  Options asked;
  asked.cleaning = Cleaning::outliers;
  const auto cleaned = reconstruct(t.samples, asked);
  EXPECT_EQ(cleaned.removed_outliers, (std::vector<int>{4000, 4001, 4002, 4003}));
}

TEST(Outliers, SamplesOfSurfacesAreNotOutliers) {
  // Curved, bordered, thin, sharp-free and noisy: each sample's neighbours vouch for it.
  EXPECT_TRUE(outlying_samples(shapes::torus(4000, major_radius, minor_radius)).empty());
  EXPECT_TRUE(outlying_samples(shapes::bumpy_sphere(3000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::hemisphere(2000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::open_cylinder(2000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::torus_knot_tube(3000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::noisy_sphere(5000, 0.4)).empty());
  EXPECT_TRUE(outlying_samples(shapes::sphere(10)).empty())
      << "fewer samples than a neighbourhood: none judged";
}

TEST(Outliers, TheAutomaticCleaningRemovesThemWithTheNoiseOnly) {
  // Clean samples keep every point unless asked: a mesh's lone vertices look like outliers.
  const Torus_with_outliers clean = torus_with_outliers(20);
  const auto kept = reconstruct(clean.samples, Options{});
  EXPECT_FALSE(kept.stats.cleaned);
  EXPECT_EQ(kept.sample_count(), clean.samples.size());

  // Noisy samples (0.4 of the spacing) are cleaned: their strays go before the smoothing, one
  // in four of them inside the sphere (20 spacings round).
  std::vector<Point<3>> noisy = shapes::noisy_sphere(5000, 0.4);
  const std::size_t on_sphere = noisy.size();
  const double spacing = std::sqrt(4 * M_PI / double(on_sphere));
  for (int i = 0; i < 20; ++i) {
    const Point<3>& p = noisy[std::size_t(i) * 211];
    const double out = 1 + (i % 4 == 0 ? -6 : 6 + i % 4) * spacing / std::hypot(p[0], p[1], p[2]);
    noisy.push_back({p[0] * out, p[1] * out, p[2] * out});
  }
  const auto cleaned = reconstruct(noisy, Options{});
  EXPECT_TRUE(cleaned.stats.cleaned);
  EXPECT_TRUE(cleaned.stats.smoothed);
  std::vector<int> strays(20);
  std::iota(strays.begin(), strays.end(), static_cast<int>(on_sphere));
  EXPECT_EQ(cleaned.removed_outliers, strays);
  EXPECT_EQ(cleaned.stats.euler_characteristic, 2);
  const std::string line = verdict(cleaned.stats).line;
  EXPECT_NE(line.find("(20 outliers removed, not on it; smoothed: noise"), std::string::npos)
      << line;
}

TEST(Outliers, WhatCannotBeCleanedIsRefusedInOneLine) {
  std::vector<Point<2>> circle;
  for (int i = 0; i < 200; ++i) circle.push_back({std::cos(i * 0.0314), std::sin(i * 0.0314)});
  for (Cleaning asked : {Cleaning::outliers, Cleaning::outliers_and_jet}) {
    Options options;
    options.cleaning = asked;
    EXPECT_THROW(reconstruct(circle, options), Input_error);
    EXPECT_THROW(reconstruct(shapes::sphere(50), options), Input_error);
  }
  Cleaning parsed = Cleaning::none;
  EXPECT_TRUE(parse_cleaning("outliers+jet", parsed));
  EXPECT_EQ(parsed, Cleaning::outliers_and_jet);
  EXPECT_TRUE(parse_cleaning("outliers", parsed));
  EXPECT_EQ(parsed, Cleaning::outliers);
  EXPECT_STREQ(to_string(Cleaning::outliers_and_jet), "outliers+jet");
}

}  // namespace
}  // namespace sculpt
