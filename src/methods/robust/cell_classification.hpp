// SPDX-License-Identifier: GPL-3.0-or-later
// The robust method's judgement of every all-sample cell of DT(S ∪ BBV): inner or outer, from the
// labelled poles alone. A cell is outer when
//   - its circumball holds an outer pole whose polar ball is not tiny beside it: inserting the
//     outer poles, as the paper's sculpting does (section 3.2), would destroy it; or
//   - its circumcentre lies in the power cell of an outer polar ball (the "power carve"): of the
//     polar balls of its own samples, the one of least power distance |x - c|² - r² is outer.
//     This is the power crust's inner/outer rule (Amenta, Choi, Kolluri 2001) applied to the
//     Delaunay cells; it removes cells that span undersampled parts, which no outer pole reaches.
//     The candidates are the poles of the cell's vertices, the balls that touch the cell: on
//     CGAL's knot1, fandisk, hand, femur, elephant, refined_elephant, bunny00 and armadillo this
//     gave the same surfaces as the nearest-power query over all poles, at a tenth of the cost.
// A cell both rules find is recorded as found by the power carve, the test asked first (below).
// The cells themselves are not changed here; manifold_carving.hpp removes them, asking the judge
// about each cell when it first needs to know.
//
// Why "not tiny": noise. Samples displaced across the surface by noise have Voronoi vertices in
// the noise band, poles whose balls are about one spacing wide and whose side is a coin toss.
// Such a pole sits at the rim of the large Delaunay balls of the other side, and an outer one
// would cut into the solid there: on 20,000 samples of a sphere with noise of 5% of the spacing,
// 25 such poles made 14 handles. As Dey & Goswami trust only big Delaunay balls under noise
// (2006), a pole destroys a cell only when its ball is at least noise_pole_ratio of the cell's
// circumball. Measured: the sphere is right up to noise of 10% of the spacing; CGAL's knot1,
// bunny00, fandisk, hand, elephant and the shared scans keep their surfaces exactly (femur
// changes, 10 -> 5 samples left off); ratios 0.25-0.4 behave alike.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <sculpt/sculpt.hpp>
#include <type_traits>
#include <vector>

#include "../../core/circumball_query.hpp"

namespace sculpt {

// How large, against a cell's circumradius, an outer pole's ball must be to destroy the cell.
inline constexpr double noise_pole_ratio = 0.3;

// Something of each outer pole (its centre, its radius), in the order of the poles.
template <int D, class Of>
auto of_outer_poles(const Reconstruction<D>& result, Of&& of) {
  std::vector<std::decay_t<decltype(of(result.poles.poles[0]))>> values;
  for (std::size_t p = 0; p < result.poles.poles.size(); ++p) {
    if (result.propagation.labels[p] == Label::outer) values.push_back(of(result.poles.poles[p]));
  }
  return values;
}

// The two polar balls of every sample, packed together (one cache line in 3D): the power carve
// reads those of the four samples of every cell, and the poles themselves lie scattered.
template <int D>
class Polar_balls {
 public:
  explicit Polar_balls(const Reconstruction<D>& result)
      : balls_(result.sample_count()), labels_(result.sample_count()) {
    const auto& poles = result.poles;
    for (std::size_t s = 0; s < balls_.size(); ++s) {
      const int pair[2] = {poles.positive_pole[s], poles.negative_pole[s]};
      for (int j = 0; j < 2; ++j) {
        const int q = pair[j];
        labels_[s][j] = q < 0 ? Label::unlabelled : result.propagation.labels[q];
        if (q < 0) continue;
        balls_[s].center[j] = poles.poles[q].center;
        balls_[s].radius2[j] = poles.poles[q].radius * poles.poles[q].radius;
      }
    }
  }

  // The label of the polar ball of least power distance |x - c|² - r² from x among the balls of
  // `samples` (p+ before p- of each, the first of equal powers).
  template <class Samples>
  Label power_cell_label(const Point<D>& x, const Samples& samples) const {
    double least = std::numeric_limits<double>::infinity();
    Label label = Label::unlabelled;
    for (int s : samples) {
      const Pair& pair = balls_[s];
      for (int j = 0; j < 2; ++j) {
        if (labels_[s][j] == Label::unlabelled) continue;
        double d2 = 0;
        for (int k = 0; k < D; ++k) d2 += (x[k] - pair.center[j][k]) * (x[k] - pair.center[j][k]);
        const double power = d2 - pair.radius2[j];
        if (power < least) {
          least = power;
          label = labels_[s][j];
        }
      }
    }
    return label;
  }

 private:
  struct alignas(64) Pair {
    std::array<Point<D>, 2> center{};
    std::array<double, 2> radius2{};
  };
  std::vector<Pair> balls_;
  std::vector<std::array<Label, 2>> labels_;
};

// The judge of the cells, asked cell by cell: the carving's flood asks only about the cells it
// reaches (on a 300k-point random torus, 2.2M of the 5.4M all-sample cells), and each verdict
// is kept, so no cell is judged twice.
template <class Traits>
class Cell_judge {
  static constexpr int D = Traits::dimension;
  using Triangulation = typename Traits::Triangulation;
  using Cell_handle = typename Traits::Cell_handle;

 public:
  Cell_judge(const Triangulation& triangulation, const Reconstruction<D>& result)
      : triangulation_(triangulation),
        outer_radii_(of_outer_poles(result, [](const Pole<D>& pole) { return pole.radius; })),
        // Strictly inside, decided exactly: the poles on the sphere (those of neighbouring cells
        // can be) do not destroy it. The query keeps its own copy of the centres.
        outer_poles_(triangulation,
                     of_outer_poles(result, [](const Pole<D>& pole) { return pole.center; }),
                     false),
        polar_balls_(result),
        sample_count_(static_cast<int>(result.sample_count())),
        verdicts_(result.delaunay.cell_count, unjudged) {}

  // 0: inner (or not an all-sample cell); else 1 + the Carve_reason it is outer for.
  std::uint8_t verdict(Cell_handle cell) const {
    std::uint8_t& memo = verdicts_[cell->info()];
    if (memo == unjudged) {
      memo = judge(cell);
      ++judged_;
    }
    return memo;
  }

  // Whether the cell numbered so has been judged, and if so whether outer: no handle needed.
  bool known(int number) const { return verdicts_[number] != unjudged; }
  bool known_outer(int number) const { return known(number) && verdicts_[number] != 0; }

  // How many cells have been judged so far.
  std::size_t judged() const { return judged_; }

 private:
  static constexpr std::uint8_t unjudged = 255;

  std::uint8_t judge(Cell_handle cell) const {
    std::array<int, D + 1> samples;
    for (int i = 0; i <= D; ++i) {
      samples[i] = cell->vertex(i)->info();
      if (samples[i] >= sample_count_) return 0;
    }
    const Point<D> x = Traits::from_cgal(Traits::circumcenter(triangulation_, cell));
    // The power test first: it reads eight balls, where the circumball query searches a tree,
    // and it finds nearly every outer cell (bunny00: 124,493 of 124,493; femur: 11,296 of
    // 12,178). The query is left for the cells it calls inner, about half.
    if (polar_balls_.power_cell_label(x, samples) == Label::outer) {
      return 1 + static_cast<int>(Carve_reason::outer_power_cell);
    }
    if (outer_poles_.holds_point(cell, x, [&](int pole, double radius) {
          return outer_radii_[pole] >= noise_pole_ratio * radius;
        })) {
      return 1 + static_cast<int>(Carve_reason::outer_pole_inside);
    }
    return 0;
  }

  const Triangulation& triangulation_;
  const std::vector<double> outer_radii_;  // of the outer poles, as the query numbers them
  const Circumball_query<Traits> outer_poles_;
  const Polar_balls<D> polar_balls_;
  int sample_count_;
  // Per cell, unjudged until asked. Asking changes nothing but this memo (a verdict depends on
  // the cell alone), hence const; one run's judge is not shared between threads.
  mutable std::vector<std::uint8_t> verdicts_;
  mutable std::size_t judged_ = 0;
};

}  // namespace sculpt
