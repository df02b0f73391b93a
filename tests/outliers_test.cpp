// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0's outlier removal (core/outlying_samples.hpp, driver/cleaning.hpp): a scanner's stray
// returns are removed before the method, where asked or with the noise of noisy samples, and the
// surface no longer reaches out to them; samples of a surface are never taken for outliers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
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
  std::vector<Point<3>> samples;  // the torus's, with the outliers among them
  std::vector<Point<3>> torus;    // the torus's alone, in their order
  std::vector<int> strays;        // where the outliers are among the samples
  double spacing = 0;
};

// 4,000 samples of the torus and `strays` outliers among them (the k-th at 100 k + 50), each off
// a sample along the normal by 4 to 9 times the spacing, outwards (the tube is only 6 spacings
// round: a stray inside it is surrounded by the wall; the inward ones are the noisy sphere's).
Torus_with_outliers torus_with_outliers(int strays) {
  Torus_with_outliers t;
  t.torus = shapes::torus(4000, major_radius, minor_radius);
  const double area = 4 * M_PI * M_PI * major_radius * minor_radius;
  t.spacing = std::sqrt(area / double(t.torus.size()));
  shapes::Portable_random random(5);
  t.samples = t.torus;
  for (int i = 0; i < strays; ++i) {
    const Point<3>& base = t.torus[std::size_t(i) * 97 % t.torus.size()];
    Point<3> normal;
    off_torus(base, &normal);
    const double height = (4 + 5 * random.unit()) * t.spacing;
    t.strays.push_back(100 * i + 50);
    t.samples.insert(
        t.samples.begin() + t.strays.back(),
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
  ASSERT_EQ(spiky.sample_count(), t.samples.size());

  Options asked;
  asked.cleaning = Cleaning::outliers;
  const auto cleaned = reconstruct(t.samples, asked);
  EXPECT_EQ(cleaned.removed_outliers, t.strays) << "every stray, and no sample of the torus";
  EXPECT_LT(outlier_detail::outliers_among(t.samples).size(), t.strays.size())
      << "one round finds them all: the rounds are not tested here";
  EXPECT_TRUE(cleaned.given_samples == t.samples);
  ASSERT_EQ(cleaned.sample_count(), t.torus.size());
  EXPECT_TRUE(std::equal(t.torus.begin(), t.torus.end(), cleaned.sites.begin()))
      << "removing is not smoothing: the samples kept are as given, in their order";
  EXPECT_TRUE(cleaned.stats.cleaned);
  EXPECT_FALSE(cleaned.stats.smoothed);
  EXPECT_EQ(cleaned.stats.outliers_removed, t.strays.size());
  EXPECT_EQ(cleaned.stats.euler_characteristic, 0);
  EXPECT_EQ(cleaned.stats.unused_samples, 0u);
  EXPECT_LT(reach_off_torus(cleaned, t.spacing), 0.5);
  const std::string line = verdict(cleaned.stats).line;
  EXPECT_TRUE(verdict(cleaned.stats).manifold) << line;
  EXPECT_NE(line.find("cleaned first (40 outliers removed, not on it)"), std::string::npos) << line;
  EXPECT_EQ(cleaned.stats.stages.front().name, "cleaning");
}

TEST(Outliers, AClusterOfStraysIsFoundUpToHalfANeighbourhood) {
  // Returns a quarter of a spacing apart, 12 spacings off the torus: each has the others among
  // its nearest, and they fit a plane together; but they are alone, the surface beyond them.
  // From 8 on (over half of the 14 nearest) they are a patch of their own.
  const Torus_with_outliers t = torus_with_outliers(0);
  Options asked;
  asked.cleaning = Cleaning::outliers;
  for (int size : {2, 4, 7, 8, 12}) {
    std::vector<Point<3>> samples = t.torus;
    shapes::Portable_random random(3);
    std::vector<int> cluster;
    for (int i = 0; i < size; ++i) {
      Point<3> stray;
      for (int k = 0; k < 3; ++k) {
        stray[k] = t.torus[0][k] + 7 * t.spacing + 0.25 * t.spacing * random.normal();
      }
      cluster.push_back(static_cast<int>(samples.size()));
      samples.push_back(stray);
    }
    EXPECT_EQ(reconstruct(samples, asked).removed_outliers,
              size < 8 ? cluster : std::vector<int>{})
        << size << " strays";
  }
}

TEST(Outliers, ReturnsAtOneSpotOrADenserPatchAreNoOutliers) {
  // Twenty returns within a billionth of a sample: judged as one spot, on the surface. A patch
  // scanned 30 times denser: its rim's samples are alone, but on the surface.
  const std::vector<Point<3>> sphere = shapes::noisy_sphere(3000, 0);
  std::vector<Point<3>> repeated = sphere;
  shapes::Portable_random random(11);
  for (int i = 0; i < 20; ++i) {
    Point<3> p = sphere[5];
    for (double& x : p) x += 1e-9 * random.normal();
    repeated.push_back(p);
  }
  EXPECT_TRUE(outlying_samples(repeated).empty());
  std::vector<Point<3>> patched = sphere;
  for (const auto& p : shapes::noisy_sphere(90000, 0, 2)) {
    if (std::hypot(p[0] - sphere[7][0], p[1] - sphere[7][1], p[2] - sphere[7][2]) < 0.2)
      patched.push_back(p);
  }
  ASSERT_GT(patched.size(), sphere.size() + 500);
  EXPECT_TRUE(outlying_samples(patched).empty());
}

TEST(Outliers, RefusalsNameThePointsAsGiven) {
  // Checked before the cleaning: a repeated point is named by its place in the input, not among
  // the samples left once five strays in front are removed.
  std::vector<Point<3>> samples;
  for (int i = 0; i < 5; ++i) samples.push_back({3.0 + i, 3.0, 3.0});
  for (const auto& p : shapes::noisy_sphere(3000, 0)) samples.push_back(p);
  samples.push_back(samples[105]);
  Options asked;
  asked.cleaning = Cleaning::outliers;
  try {
    reconstruct(samples, asked);
    ADD_FAILURE() << "the repeated point was not refused";
  } catch (const Duplicate_points& refusal) {
    EXPECT_NE(std::string(refusal.what()).find("the 3006th point duplicates the 106th point"),
              std::string::npos)
        << refusal.what();
  }
}

TEST(Outliers, SamplesOfSurfacesAreNotOutliers) {
  // Curved, bordered, thin, sharp-free and noisy: each sample's neighbours vouch for it.
  EXPECT_TRUE(outlying_samples(shapes::torus(4000, major_radius, minor_radius)).empty());
  EXPECT_TRUE(outlying_samples(shapes::bumpy_sphere(3000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::hemisphere(2000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::open_cylinder(2000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::torus_knot_tube(3000)).empty());
  EXPECT_TRUE(outlying_samples(shapes::noisy_sphere(5000, 0.4)).empty());
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
  std::vector<Point<3>> line;
  for (int i = 0; i < 200; ++i) line.push_back({0.1 * i, 0.2 * i, 0.3 * i});
  // The refusal's one line, or "" where there is none.
  const auto refusal = [](const auto& samples, Cleaning asked) -> std::string {
    Options options;
    options.cleaning = asked;
    try {
      reconstruct(samples, options);
    } catch (const Input_error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return e.what();
    }
    return "";
  };
  for (Cleaning asked : {Cleaning::outliers, Cleaning::outliers_and_jet}) {
    EXPECT_NE(refusal(circle, asked).find("cleans surfaces' samples (3D points), not curves'"),
              std::string::npos);
    EXPECT_NE(refusal(shapes::sphere(50), asked).find("needs at least 100 samples, not 50"),
              std::string::npos);
    // Checked before any cleaning: smoothing would move them off their line.
    EXPECT_NE(refusal(line, asked).find("all points are coplanar"), std::string::npos);
  }
  EXPECT_NE(refusal(shapes::sphere(50), Cleaning::outliers).find("by its nearest (14)"),
            std::string::npos);
  Cleaning parsed = Cleaning::none;
  EXPECT_TRUE(parse_cleaning("outliers+jet", parsed));
  EXPECT_EQ(parsed, Cleaning::outliers_and_jet);
  EXPECT_TRUE(parse_cleaning("outliers", parsed));
  EXPECT_EQ(parsed, Cleaning::outliers);
  EXPECT_STREQ(to_string(Cleaning::outliers_and_jet), "outliers+jet");
}

}  // namespace
}  // namespace sculpt
