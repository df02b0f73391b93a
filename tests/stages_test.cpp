// SPDX-License-Identifier: GPL-3.0-or-later
// The intermediate stages are what the viewer shows and a student reads: check that each one
// means what the API says it means.
#include <cmath>
#include <map>
#include <set>

#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

template <int D>
double distance(const Point<D>& a, const Point<D>& b) {
  double sum = 0;
  for (int k = 0; k < D; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum);
}

template <int D>
double dot(const Point<D>& a, const Point<D>& b, const Point<D>& origin) {
  double sum = 0;
  for (int k = 0; k < D; ++k) sum += (a[k] - origin[k]) * (b[k] - origin[k]);
  return sum;
}

template <int D>
void check_stages(const Reconstruction<D>& r) {
  const int n = static_cast<int>(r.sample_count());
  const auto& poles = r.poles.poles;

  // 1. The box: 2^D corners, box_factor times the samples' extent, around the same centre.
  Point<D> lo = r.sites[0], hi = r.sites[0];
  for (int s = 0; s < n; ++s) {
    for (int k = 0; k < D; ++k)
      lo[k] = std::min(lo[k], r.sites[s][k]), hi[k] = std::max(hi[k], r.sites[s][k]);
  }
  for (int c = n; c < n + (1 << D); ++c) {
    EXPECT_EQ(r.kind_of_site(c), Site_kind::box_corner);
    for (int k = 0; k < D; ++k) {
      EXPECT_NEAR(std::abs(r.sites[c][k] - 0.5 * (lo[k] + hi[k])),
                  0.5 * r.options.box_factor * (hi[k] - lo[k]), 1e-9);
    }
  }
  ASSERT_EQ(r.delaunay.cells.size(), r.delaunay.cell_count);

  // 2. Poles: each is the circumcentre of its cell, and the pair of each sample lies on both
  // sides of it, p+ at least as far as p-.
  for (const auto& pole : poles) {
    const auto& cell = r.delaunay.cells[pole.cell];
    bool touches_corner = false;
    for (int v : cell) {
      EXPECT_NEAR(distance<D>(pole.center, r.sites[v]), pole.radius, 1e-7 * (1 + pole.radius));
      touches_corner = touches_corner || r.kind_of_site(v) == Site_kind::box_corner;
    }
    EXPECT_EQ(pole.convex, touches_corner);
  }
  for (int s = 0; s < n; ++s) {
    const int plus = r.poles.positive_pole[s], minus = r.poles.negative_pole[s];
    ASSERT_GE(plus, 0);
    ASSERT_GE(minus, 0);
    EXPECT_LT(dot<D>(poles[plus].center, poles[minus].center, r.sites[s]), 0.0);
    EXPECT_GE(poles[plus].radius, poles[minus].radius);
    const auto partners = r.poles.partners_of(plus);
    EXPECT_TRUE(std::find(partners.begin(), partners.end(), minus) != partners.end());
  }

  // 3-4. Every labelling event is justified by its source, which was labelled before it.
  std::vector<int> labelled_at(poles.size(), -1);
  for (std::size_t i = 0; i < r.propagation.events.size(); ++i) {
    const auto& e = r.propagation.events[i];
    ASSERT_EQ(labelled_at[e.pole], -1) << "pole " << e.pole << " labelled twice";
    labelled_at[e.pole] = static_cast<int>(i);
    EXPECT_EQ(r.propagation.labels[e.pole], e.label);
    if (e.reason == Label_reason::convex_seed) {
      EXPECT_TRUE(poles[e.pole].convex);
      EXPECT_EQ(e.label, Label::outer);
      continue;
    }
    ASSERT_GE(e.source, 0);
    ASSERT_GE(labelled_at[e.source], 0);
    EXPECT_LT(labelled_at[e.source], static_cast<int>(i));
    const Label source_label = r.propagation.labels[e.source];
    if (e.reason == Label_reason::pairing) {
      EXPECT_NE(e.label, source_label);
      const auto partners = r.poles.partners_of(e.source);
      EXPECT_TRUE(std::find(partners.begin(), partners.end(), e.pole) != partners.end());
    } else {
      EXPECT_EQ(e.label, source_label);
      const double half_side = poles[e.source].radius / std::sqrt(double(D));
      for (int k = 0; k < D; ++k) {
        EXPECT_LT(std::abs(poles[e.pole].center[k] - poles[e.source].center[k]), half_side);
      }
    }
  }
  std::size_t unlabelled = 0;
  for (std::size_t p = 0; p < poles.size(); ++p) unlabelled += labelled_at[p] < 0;
  EXPECT_EQ(unlabelled, r.propagation.unlabelled);

  // 5-6. The inserted poles are sites of DT(S ∪ OUP), outer and not convex when closed.
  for (std::size_t k = 0; k < r.insertion.inserted_poles.size(); ++k) {
    const int pole = r.insertion.inserted_poles[k];
    const int site = n + (1 << D) + static_cast<int>(k);
    EXPECT_EQ(r.kind_of_site(site), Site_kind::pole);
    EXPECT_EQ(r.pole_of_site(site), pole);
    EXPECT_FALSE(poles[pole].convex);
    if (r.options.kind == Surface_kind::closed) {
      EXPECT_EQ(r.propagation.labels[pole], Label::outer);
    }
  }
  ASSERT_EQ(r.sculpted_delaunay.cells.size(), r.sculpted_delaunay.cell_count);

  // 7. The solid is exactly the all-sample cells of DT(S ∪ OUP).
  std::size_t all_sample_cells = 0;
  for (const auto& cell : r.sculpted_delaunay.cells) {
    all_sample_cells += std::all_of(cell.begin(), cell.end(), [&](int v) { return v < n; });
  }
  EXPECT_EQ(all_sample_cells, r.solid.size());
  EXPECT_EQ(r.stats.solid_cells, r.solid.size());

  // Timings: every stage measured, in order.
  std::vector<std::string> names;
  for (const auto& stage : r.stats.stages) names.push_back(stage.name);
  EXPECT_EQ(names, (std::vector<std::string>{"checks", "delaunay", "poles", "seeds", "propagation",
                                             "insertion", "solid", "surface", "topology"}));
}

Options paper_method() {
  Options options;
  options.method = Method::paper;
  options.kind = Surface_kind::closed;
  return options;
}

Options robust_closed() {
  Options options;
  options.kind = Surface_kind::closed;
  return options;
}

// The robust method's stages: a labelling in which every event is justified by an earlier one,
// and a carving that removes distinct all-sample cells, leaving the solid whose boundary is the
// surface.
template <int D>
void check_robust_stages(const Reconstruction<D>& r) {
  std::vector<std::string> names;
  for (const auto& stage : r.stats.stages) names.push_back(stage.name);
  EXPECT_EQ(names, (std::vector<std::string>{"checks", "delaunay", "poles", "seeds", "labelling",
                                             "carving", "solid", "surface", "topology"}));
  std::vector<int> labelled_at(r.poles.poles.size(), -1);
  for (std::size_t i = 0; i < r.propagation.events.size(); ++i) {
    const auto& event = r.propagation.events[i];
    ASSERT_EQ(labelled_at[event.pole], -1) << "pole labelled twice";
    labelled_at[event.pole] = static_cast<int>(i);
    EXPECT_EQ(r.propagation.labels[event.pole], event.label);
    EXPECT_GE(event.weight, 0.0f);
    EXPECT_LE(event.weight, 1.0f);
    if (event.reason == Label_reason::convex_seed) {
      EXPECT_TRUE(r.poles.poles[event.pole].convex);
    } else {
      ASSERT_GE(event.source, 0);
      EXPECT_GE(labelled_at[event.source], 0) << "labelled by a pole not yet labelled";
      EXPECT_EQ(event.label == r.propagation.labels[event.source],
                event.reason == Label_reason::ball_overlap);
    }
  }
  EXPECT_TRUE(r.insertion.inserted_poles.empty()) << "the robust method inserts no pole";
  const int n = static_cast<int>(r.sample_count());
  std::set<Cell<D>> solid;
  std::vector<bool> carved(r.delaunay.cells.size(), false);
  for (const auto& event : r.carving.events) {
    ASSERT_LT(static_cast<std::size_t>(event.cell), r.delaunay.cells.size());
    EXPECT_FALSE(carved[event.cell]) << "a cell carved twice";
    carved[event.cell] = true;
    for (int v : r.delaunay.cells[event.cell]) EXPECT_LT(v, n) << "carved a non-sample cell";
  }
  for (std::size_t c = 0; c < r.delaunay.cells.size(); ++c) {
    bool all_samples = true;
    for (int v : r.delaunay.cells[c]) all_samples = all_samples && v < n;
    if (all_samples && !carved[c]) solid.insert(r.delaunay.cells[c]);
  }
  EXPECT_EQ(solid, std::set<Cell<D>>(r.solid.begin(), r.solid.end()));
  // Each surface facet is a facet of exactly one solid cell.
  std::map<Facet<D>, int> solid_facets;
  for (const auto& cell : r.solid) {
    for (int skip = 0; skip <= D; ++skip) {
      Facet<D> f;
      for (int j = 0, k = 0; j <= D; ++j) {
        if (j != skip) f[k++] = cell[j];
      }
      std::sort(f.begin(), f.end());
      ++solid_facets[f];
    }
  }
  for (auto f : r.surface) {
    std::sort(f.begin(), f.end());
    EXPECT_EQ(solid_facets[f], 1);
  }
}

TEST(Stages, Curve2d) {
  check_stages(reconstruct(shapes::star(150).samples, paper_method()));
  check_robust_stages(reconstruct(shapes::star(150).samples, robust_closed()));
}

TEST(Stages, Surface3d) {
  check_stages(reconstruct(shapes::torus(2000), paper_method()));
  check_robust_stages(reconstruct(shapes::torus(2000), robust_closed()));
}

TEST(Stages, BorderedSurface3d) {
  Options options = paper_method();
  options.kind = Surface_kind::bordered;
  const auto result = reconstruct(shapes::saddle(20), options);
  check_stages(result);
  ASSERT_EQ(result.seeds.outer_seeds.size(), 1u);
  // The default seed is p+ of the lowest-index sample whose p+ is convex.
  int first = -1;
  for (int s = 0; first < 0; ++s) {
    if (result.poles.poles[result.poles.positive_pole[s]].convex)
      first = result.poles.positive_pole[s];
  }
  EXPECT_EQ(result.seeds.outer_seeds[0], first);
}

TEST(Stages, KeepTriangulationsOffStillCountsCells) {
  Options options = paper_method();
  options.keep_triangulations = false;
  const auto result = reconstruct(shapes::torus(1000), options);
  EXPECT_TRUE(result.delaunay.cells.empty());
  EXPECT_GT(result.delaunay.cell_count, 0u);
  EXPECT_EQ(result.sculpted_delaunay.cell_count, 0u);  // closed: answered without inserting
  options.kind = Surface_kind::bordered;
  const auto bordered = reconstruct(shapes::torus(1000), options);
  EXPECT_TRUE(bordered.sculpted_delaunay.cells.empty());
  EXPECT_GT(bordered.sculpted_delaunay.cell_count, bordered.delaunay.cell_count);
}

TEST(Stages, ProgressCanCancel) {
  Options options;
  int calls = 0;
  options.progress = [&](const Progress& progress) {
    ++calls;
    return std::string(progress.stage) != "poles";
  };
  EXPECT_THROW(reconstruct(shapes::sphere(500), options), Cancelled);
  EXPECT_GE(calls, 3);
}

TEST(Stages, BoxFactorIsAParameter) {
  Options options = paper_method();
  options.box_factor = 1.5;
  const auto result = reconstruct(shapes::star(100).samples, options);
  check_stages(result);
  EXPECT_EQ(result.stats.boundary_ridges, 0u);
}

}  // namespace
}  // namespace sculpt
