// SPDX-License-Identifier: GPL-3.0-or-later
// The poles and the Voronoi diagram they come from, drawn on the stages voronoi to outer-concave
// and sculpted-delaunay, with the polar balls at any stage asked for, and wherever a sample or a
// pole is picked (--focus-sample, --focus-pole): the Voronoi edges, the poles by label, the polar
// balls, the labelling replay's event, a sample's Voronoi cell with its poles, balls and inscribed
// cubes. Its own file: the medial side of the method, apart from the cells carved and the result.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <sculpt/sculpt.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "builder_context.hpp"
#include "layer_helpers.hpp"
#include "palette.hpp"
#include "scene.hpp"
#include "simplex_geometry.hpp"

namespace sculpt::scene {

// Voronoi edges join the circumcentres of Delaunay cells that share a facet.
template <int D>
void voronoi_edges(const Builder_context<D>& ctx) {
  require_cells(ctx.r.delaunay);
  const auto& cells = ctx.r.delaunay.cells;
  std::vector<Point<D>> centers(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    std::array<Point<D>, D + 1> corners;
    for (int i = 0; i <= D; ++i) corners[i] = ctx.r.sites[cells[c][i]];
    centers[c] = circumcenter<D>(corners);
  }
  Layer& layer = ctx.add("voronoi", "Voronoi edges", Primitive::lines, palette::voronoi_edge, 1.5f);
  for (const auto& [a, b] : cells_sharing_a_facet<D>(cells)) {
    layer.positions.push_back(vec(centers[a]));
    layer.positions.push_back(vec(centers[b]));
  }
}

template <int D, class Keep>
Layer& poles_where(const Builder_context<D>& ctx, const char* id, const std::string& label,
                   Color color, Keep keep) {
  Layer& layer = ctx.add(id, label, Primitive::points, color, D == 2 ? 7 : 4);
  const auto& poles = ctx.r.poles.poles;
  for (int p = 0; p < static_cast<int>(poles.size()); ++p) {
    if (keep(p)) layer.positions.push_back(vec(poles[p].center));
  }
  return layer;
}

// A layer of the balls of `poles`, thinned to `ball_limit` evenly (an empty one stays out of
// the legend; the layer polar-balls names them all, as --layers takes it).
template <int D>
void balls_layer(const Builder_context<D>& ctx, const char* id, const std::string& label,
                 Color color, const std::vector<int>& poles) {
  const std::size_t limit = ctx.request.ball_limit > 0 ? std::size_t(ctx.request.ball_limit) : 0;
  const std::size_t count = limit > 0 ? std::min(limit, poles.size()) : poles.size();
  Layer& layer = ctx.add(id,
                         label + (count < poles.size() ? " (" + std::to_string(count) + " of " +
                                                             std::to_string(poles.size()) + ")"
                                                       : ""),
                         Primitive::balls, color, 1.0f);
  layer.translucent = D == 3;  // outlines of overlapping spheres are unreadable in 3D
  for (std::size_t k = 0; k < count; ++k) {
    const auto& pole = ctx.r.poles.poles[poles[k * poles.size() / count]];
    layer.positions.push_back(vec(pole.center));
    layer.radii.push_back(float(pole.radius));
  }
}

// The polar balls: in 2D the paper's circles, one colour; in 3D translucent spheres, the
// inner and outer balls apart (by the labels known at this stage: at the labelling replay,
// those given so far; before it, the final ones), at most `ball_limit` of each kind.
template <int D>
void polar_balls(const Builder_context<D>& ctx) {
  const auto& poles = ctx.r.poles.poles;
  const int every = std::max(1, ctx.request.ball_every);
  // In 3D, a ball larger than the samples' box would wrap the camera in a translucent fog:
  // those (outer poles far out) are left out, the medial balls inside and near stay.
  float diagonal = 0;
  for (int c = 0; c < 3; ++c)
    diagonal +=
        (ctx.scene.upper[c] - ctx.scene.lower[c]) * (ctx.scene.upper[c] - ctx.scene.lower[c]);
  const float largest = D == 3 ? 0.5f * std::sqrt(diagonal) : INFINITY;
  std::vector<int> shown;
  for (std::size_t p = 0; p < poles.size(); ++p) {
    // Convex poles' huge balls hide everything.
    if (!poles[p].convex && p % every == 0 && poles[p].radius <= largest) shown.push_back(int(p));
  }
  if constexpr (D == 2) {
    balls_layer(ctx, "polar-balls", "polar circles", palette::polar_ball, shown);
  } else {
    const std::vector<Label> labels = labels_at_stage(ctx.r, ctx.request);
    std::vector<int> of_kind[3];
    for (int p : shown) of_kind[labels.empty() ? 0 : int(labels[p])].push_back(p);
    const auto translucent = [&](Color c, float share = 1) {
      return Color{c.r, c.g, c.b, share * ctx.request.ball_opacity};
    };
    balls_layer(ctx, "polar-balls", labels.empty() ? "polar balls" : "polar balls not yet labelled",
                translucent(palette::polar_ball_3d), of_kind[int(Label::unlabelled)]);
    // Before the labelling the sides come from its end, and the legend says so.
    const std::string later = ctx.request.stage < Stage::propagation ? " (as labelled later)" : "";
    balls_layer(ctx, "inner-balls", "inner polar balls" + later, translucent(palette::inner_ball),
                of_kind[int(Label::inner)]);
    // Fainter: the outer balls are the larger, and would hide the medial axis inside.
    balls_layer(ctx, "outer-balls", "outer polar balls" + later,
                translucent(palette::outer_ball, 0.35f), of_kind[int(Label::outer)]);
  }
}

template <int D>
void seeds(const Builder_context<D>& ctx) {
  const auto& seeds = ctx.r.seeds;
  std::vector<bool> outer(ctx.r.poles.poles.size(), false), inner(ctx.r.poles.poles.size(), false);
  for (int seed : seeds.outer_seeds) {
    outer[seed] = true;
    for (int partner : ctx.r.poles.partners_of(seed)) inner[partner] = !outer[partner];
  }
  poles_where(ctx, "other-poles", "other poles", palette::unlabelled_pole,
              [&](int p) { return !outer[p] && !inner[p]; });
  poles_where(ctx, "inner-seeds", "inner seeds (paired with outer seeds)", palette::inner_pole,
              [&](int p) { return inner[p]; });
  poles_where(ctx, "outer-seeds", "outer seeds (convex poles)", palette::convex_pole,
              [&](int p) { return outer[p]; });
}

template <int D>
void labelled_poles(const Builder_context<D>& ctx, const std::vector<Label>& labels,
                    bool only_inserted) {
  std::vector<bool> inserted(labels.size(), !only_inserted);
  for (int p : ctx.r.insertion.inserted_poles) inserted[p] = true;
  const bool bordered = ctx.r.options.kind == Surface_kind::bordered;
  if (!only_inserted) {
    poles_where(ctx, "unlabelled-poles", "unlabelled poles", palette::unlabelled_pole,
                [&](int p) { return labels[p] == Label::unlabelled; });
  }
  poles_where(ctx, "inner-poles", "inner poles", palette::inner_pole,
              [&](int p) { return labels[p] == Label::inner && (inserted[p] || !bordered); });
  poles_where(ctx, "outer-poles", only_inserted ? "outer concave poles" : "outer poles",
              palette::outer_pole(D),
              [&](int p) { return labels[p] == Label::outer && inserted[p]; });
}

// Labelled poles that were offered the other label (paper: a conflict; robust: evidence at
// least as strong as their own). Only drawn when there are some.
// The poles offered a label against their own, up to `shown` events of the replay.
template <int D>
void contradicted_poles(const Builder_context<D>& ctx, const std::vector<Label>& labels,
                        long shown = -1) {
  std::vector<bool> contradicted(labels.size(), false);
  for (const auto& offer : ctx.r.propagation.conflicts) {
    if (shown >= 0 && offer.after_events > shown) continue;
    if (labels[offer.pole] != Label::unlabelled) contradicted[offer.pole] = true;
  }
  if (std::find(contradicted.begin(), contradicted.end(), true) == contradicted.end()) return;
  const bool paper = ctx.r.options.method == Method::paper;
  poles_where(
      ctx, "contradicted-poles",
      paper ? "poles offered both labels (conflicts)" : "poles contradicted by strong evidence",
      palette::contradicted_pole, [&](int p) { return bool(contradicted[p]); });
}

template <int D>
void inscribed_cube(const Pole<D>& pole, Layer& layer) {
  const double h = pole.radius / std::sqrt(double(D));
  const auto corner = [&](int bits) {
    Point<D> p = pole.center;
    for (int k = 0; k < D; ++k) p[k] += (bits >> k) & 1 ? h : -h;
    return vec(p);
  };
  for (int a = 0; a < (1 << D); ++a) {
    for (int k = 0; k < D; ++k) {
      const int b = a | (1 << k);  // each edge once, from its lower corner
      if (b != a) {
        layer.positions.push_back(corner(a));
        layer.positions.push_back(corner(b));
      }
    }
  }
}

template <int D>
void propagation(const Builder_context<D>& ctx) {
  if (ctx.r.options.method == Method::robust) {
    ctx.scene.title = "Pole labelling by confidence (robust method)";
  }
  const auto& events = ctx.r.propagation.events;
  const std::size_t shown =
      ctx.request.step < 0 ? events.size() : std::min<std::size_t>(ctx.request.step, events.size());
  std::vector<Label> labels(ctx.r.poles.poles.size(), Label::unlabelled);
  for (std::size_t i = 0; i < shown; ++i) labels[events[i].pole] = events[i].label;
  labelled_poles(ctx, labels, /*only_inserted=*/false);
  contradicted_poles(ctx, labels, long(shown));
  if (shown == 0) return;
  // The latest event: the pole just labelled, and the ball (and cube) that labelled it.
  const Labelling_event& last = events[shown - 1];
  if (last.source >= 0) {
    const auto& source = ctx.r.poles.poles[last.source];
    Layer& ball = ctx.add("source-ball", "labelling polar ball", Primitive::balls,
                          palette::source_ball, 2.0f);
    ball.positions.push_back(vec(source.center));
    ball.radii.push_back(float(source.radius));
    if (last.reason == Label_reason::inscribed_cube) {
      Layer& cube = ctx.add("source-cube", D == 2 ? "its inscribed square" : "its inscribed cube",
                            Primitive::lines, palette::source_cube, 2.0f);
      inscribed_cube(source, cube);
    }
  }
  Layer& current = ctx.add("current-pole", "pole just labelled", Primitive::points,
                           palette::current_pole, D == 2 ? 12 : 9);
  current.positions.push_back(vec(ctx.r.poles.poles[last.pole].center));
}

// The Voronoi cell of a sample: the Voronoi edges dual to the Delaunay facets that contain it.
template <int D>
void voronoi_cell(const Builder_context<D>& ctx, int sample) {
  if (ctx.r.delaunay.cells.size() != ctx.r.delaunay.cell_count) return;
  std::vector<Cell<D>> incident;
  for (const auto& cell : ctx.r.delaunay.cells) {
    if (std::find(cell.begin(), cell.end(), sample) != cell.end()) incident.push_back(cell);
  }
  Layer& layer = ctx.add("focus-cell", "the sample's Voronoi cell", Primitive::lines,
                         palette::focus_cell, 2.5f);
  for (const auto& [a, b] : cells_sharing_a_facet<D>(incident)) {
    std::array<Point<D>, D + 1> corners_a, corners_b;
    for (int i = 0; i <= D; ++i) {
      corners_a[i] = ctx.r.sites[incident[a][i]];
      corners_b[i] = ctx.r.sites[incident[b][i]];
    }
    layer.positions.push_back(vec(circumcenter<D>(corners_a)));
    layer.positions.push_back(vec(circumcenter<D>(corners_b)));
  }
}

template <int D>
void focus_pole(const Builder_context<D>& ctx, int pole) {
  if (pole >= static_cast<int>(ctx.r.poles.poles.size())) {
    throw std::invalid_argument("no pole " + std::to_string(pole));
  }
  const auto& p = ctx.r.poles.poles[pole];
  Layer& ball =
      ctx.add("picked-ball", "the pole's polar ball", Primitive::balls, palette::focus_ball, 2.0f);
  ball.positions.push_back(vec(p.center));
  ball.radii.push_back(float(p.radius));
  for (const auto& event : ctx.r.propagation.events) {
    if (event.pole != pole || event.source < 0) continue;
    Layer& source = ctx.add("picked-source", "the pole that labelled it", Primitive::points,
                            palette::convex_pole, D == 2 ? 11 : 8);
    source.positions.push_back(vec(ctx.r.poles.poles[event.source].center));
  }
  Layer& picked = ctx.add("picked-pole", "picked pole", Primitive::points, palette::picked_pole,
                          D == 2 ? 12 : 9);
  picked.positions.push_back(vec(p.center));
}

template <int D>
void focus(const Builder_context<D>& ctx, int sample) {
  if (sample >= ctx.n) throw std::invalid_argument("no sample " + std::to_string(sample));
  // The sample itself, larger and darker than the others (drawn under them: a ring).
  ctx.add("picked-sample", "picked sample", Primitive::points, palette::picked_sample,
          D == 2 ? 14 : 11)
      .positions.push_back(vec(ctx.r.sites[sample]));
  voronoi_cell(ctx, sample);
  Layer& balls = ctx.add("focus-balls", "the sample's polar balls", Primitive::balls,
                         palette::focus_ball, 2.0f);
  Layer& cubes = ctx.add("focus-cubes", D == 2 ? "inscribed squares" : "inscribed cubes",
                         Primitive::lines, palette::inscribed_cube, 2.0f);
  Layer& poles = ctx.add("focus-poles", "the sample's poles", Primitive::points,
                         palette::picked_pole, D == 2 ? 10 : 8);
  for (int pole : {ctx.r.poles.positive_pole[sample], ctx.r.poles.negative_pole[sample]}) {
    if (pole < 0) continue;
    const auto& p = ctx.r.poles.poles[pole];
    balls.positions.push_back(vec(p.center));
    balls.radii.push_back(float(p.radius));
    inscribed_cube(p, cubes);
    poles.positions.push_back(vec(p.center));
  }
}

}  // namespace sculpt::scene
