// SPDX-License-Identifier: GPL-3.0-or-later
// Turns a stage of a reconstruction into layers. One builder serves both dimensions: 2D
// positions get z = 0, and the few differences (cube or square, circle or sphere) follow D.
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>

#include "carving_replay.hpp"
#include "clipping.hpp"
#include "colours.hpp"
#include "core/facet_orientation.hpp"
#include "cut_cells.hpp"
#include "growth_stages.hpp"
#include "handle_layers.hpp"
#include "layer_helpers.hpp"
#include "palette.hpp"
#include "scene.hpp"
#include "section.hpp"
#include "simplex_geometry.hpp"

namespace sculpt::scene {
namespace {

template <int D>
class Scene_builder {
 public:
  Scene_builder(const Reconstruction<D>& r, const Request& request)
      : r_(r), request_(request), n_(static_cast<int>(r.sample_count())) {
    scene_.dimension = D;
    scene_.title = stage_title(request.stage);
    fit_bounds();
  }

  Scene build() {
    require_stage(r_.options.method, D, request_.stage);
    switch (request_.stage) {
      case Stage::samples:
        if (!r_.given_samples.empty()) smoothing();
        break;
      case Stage::delaunay:
        require_cells(r_.delaunay);
        edges_of(r_.delaunay.cells, "delaunay", "Delaunay edges DT(S + BBV)",
                 palette::delaunay_edge);
        break;
      case Stage::hull:
        hull();
        break;
      case Stage::voronoi:
        voronoi_edges();
        break;
      case Stage::poles:
        // Thousands of spheres hide everything in 3D: there they are shown only when asked for.
        if (D == 2 || wants_polar_balls()) polar_balls();
        poles_where("poles", "poles", palette::pole, [](int) { return true; });
        break;
      case Stage::seeds:
        seeds();
        break;
      case Stage::propagation:
        propagation();
        break;
      case Stage::outer_concave:
        labelled_poles(r_.propagation.labels, /*only_inserted=*/r_.options.method == Method::paper);
        contradicted_poles(r_.propagation.labels);
        break;
      case Stage::carving:
        carving();
        break;
      case Stage::sculpted_delaunay:
        if (joins_neighbours(r_.options.method, r_.options.kind, D)) {
          scene_.title = "No cells carved: open curves join each sample to its nearest neighbours";
          break;
        }
        if (!inserts_poles(r_.options.method, r_.options.kind, D)) {
          // The robust method inserts no pole: it carves the hull's cells directly.
          scene_.title = "Carved hull: the cells left after carving (robust method)";
          edges_of(r_.solid, "carved-hull", "edges of the cells left", palette::delaunay_edge);
          labelled_poles(r_.propagation.labels, /*only_inserted=*/false);
          break;
        }
        // Without the triangulations kept, the solid was read off the first DT by queries and
        // DT(S + OUP) never built.
        if (!r_.options.keep_triangulations) throw std::invalid_argument(triangulations_not_kept);
        require_cells(r_.sculpted_delaunay);
        edges_of(r_.sculpted_delaunay.cells, "sculpted-delaunay", "Delaunay edges DT(S + OUP)",
                 palette::delaunay_edge);
        labelled_poles(r_.propagation.labels, /*only_inserted=*/true);
        break;
      case Stage::crust_delaunay:
        crust_delaunay();
        break;
      case Stage::candidates:
        candidates();
        break;
      case Stage::front:
      case Stage::alpha:
        if constexpr (D == 3) {
          if (request_.stage == Stage::front)
            front_growth(layers_, scene_, r_, request_.step);
          else
            alpha_growth(layers_, scene_, r_, request_);
        }
        break;
      case Stage::solid:
        if (joins_neighbours(r_.options.method, r_.options.kind, D)) {
          scene_.title = "No solid: open curves bound no region";
          break;
        }
        solid();
        break;
      case Stage::surface:
        surface();
        break;
    }
    if (request_.stage != Stage::poles && wants_polar_balls()) polar_balls();
    if (request_.focus_sample >= 0) focus(request_.focus_sample);
    if (request_.focus_pole >= 0) focus_pole(request_.focus_pole);
    // Dense samples would cover a shaded surface or solid: there they are shown when asked for.
    const bool shaded =
        D == 3 && (request_.stage == Stage::surface || request_.stage == Stage::solid ||
                   request_.stage == Stage::hull || request_.stage == Stage::carving ||
                   request_.stage == Stage::front || request_.stage == Stage::alpha);
    // The growing stages draw their own samples: those not yet reached.
    const bool grows = request_.stage == Stage::front || request_.stage == Stage::alpha;
    if (!grows && (!shaded || requested("samples"))) samples();
    scene_.layers.assign(std::make_move_iterator(layers_.begin()),
                         std::make_move_iterator(layers_.end()));
    select_layers();
    if (request_.neighbourhood && request_.focus_sample >= 0) keep_near_focus();
    return std::move(scene_);
  }

  bool wants_polar_balls() const {
    return request_.polar_balls || requested("polar-balls") || requested("inner-balls") ||
           requested("outer-balls");
  }

  // The neighbourhood view: what lies within 1.5 times the distance of the picked sample's
  // 4th (2D) or 12th (3D) nearest sample: its ring of neighbours and a little beyond.
  void keep_near_focus() {
    const Point<D>& s = r_.sites[request_.focus_sample];
    std::vector<double> distances;
    for (int i = 0; i < n_; ++i) {
      double d = 0;
      for (int c = 0; c < D; ++c) d += (r_.sites[i][c] - s[c]) * (r_.sites[i][c] - s[c]);
      distances.push_back(d);
    }
    const std::size_t k = std::min<std::size_t>(D == 2 ? 4 : 12, distances.size() - 1);
    std::nth_element(distances.begin(), distances.begin() + k, distances.end());
    const float radius = 1.5f * float(std::sqrt(distances[k]));
    // The picked sample's own cell, poles and balls stay whole: they are what was asked for.
    keep_near(scene_, vec(s), radius, {"focus-cell", "focus-balls", "focus-poles"});
    // A few dozen points, seen close: drawn larger, so each is seen as a sample or a pole.
    for (auto& layer : scene_.layers) {
      if (layer.primitive == Primitive::points) layer.size *= 2.5f;
    }
    // The camera fits the neighbourhood: it is what the picture is about.
    for (int c = 0; c < 3; ++c) {
      scene_.lower[c] = vec(s)[c] - (c < D ? radius : 0);
      scene_.upper[c] = vec(s)[c] + (c < D ? radius : 0);
    }
  }

 private:
  bool requested(const char* id) const {
    return std::find(request_.layers.begin(), request_.layers.end(), id) != request_.layers.end();
  }

  Layer& add(const char* id, const std::string& label, Primitive primitive, Color color,
             float size) {
    return add_layer(layers_, id, label, primitive, color, size);
  }

  void fit_bounds() {
    scene_.lower = scene_.upper = vec(r_.sites[0]);
    for (int s = 0; s < n_; ++s) {
      const Vec3 p = vec(r_.sites[s]);
      for (int k = 0; k < 3; ++k) {
        scene_.lower[k] = std::min(scene_.lower[k], p[k]);
        scene_.upper[k] = std::max(scene_.upper[k], p[k]);
      }
    }
  }

  void samples() {
    Layer& layer = add("samples", "samples S", Primitive::points, palette::sample, D == 2 ? 5 : 3);
    for (int s = 0; s < n_; ++s) layer.positions.push_back(vec(r_.sites[s]));
  }

  // Stage 0, when the samples were smoothed: where they were given, and how far each moved.
  void smoothing() {
    Layer& given = add("given-samples", "samples as given (before smoothing)", Primitive::points,
                       palette::given_sample, D == 2 ? 4 : 2);
    Layer& moves =
        add("smoothing", "moved by the smoothing", Primitive::lines, palette::smoothing_move, 1.0f);
    for (int s = 0; s < n_; ++s) {
      given.positions.push_back(vec(r_.given_samples[s]));
      moves.positions.push_back(vec(r_.given_samples[s]));
      moves.positions.push_back(vec(r_.sites[s]));
    }
  }

  static constexpr const char* triangulations_not_kept =
      "this stage needs the triangulations, which the reconstruction did not keep "
      "(keep_triangulations)";

  void require_cells(const Delaunay_stage<D>& stage) const {
    if (stage.cells.size() != stage.cell_count)
      throw std::invalid_argument(triangulations_not_kept);
  }

  void edges_of(const std::vector<Cell<D>>& cells, const char* id, const std::string& label,
                Color color) {
    edges_of(cells, id, label, color, [&](int site) { return r_.sites[site]; });
  }

  // The same, for cells whose vertices are placed by `position` (a site index to a point).
  template <class Position>
  void edges_of(const std::vector<Cell<D>>& cells, const char* id, const std::string& label,
                Color color, Position position) {
    std::vector<std::pair<int, int>> edges;
    for (const auto& cell : cells) {
      for (int i = 0; i <= D; ++i) {
        for (int j = i + 1; j <= D; ++j) edges.push_back(std::minmax(cell[i], cell[j]));
      }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    Layer& layer = add(id, label, Primitive::lines, color, D == 2 ? 1.5f : 1.0f);
    for (const auto& [a, b] : edges) {
      layer.positions.push_back(vec(position(a)));
      layer.positions.push_back(vec(position(b)));
    }
  }

  // Voronoi edges join the circumcentres of Delaunay cells that share a facet.
  void voronoi_edges() {
    require_cells(r_.delaunay);
    const auto& cells = r_.delaunay.cells;
    std::vector<Point<D>> centers(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      std::array<Point<D>, D + 1> corners;
      for (int i = 0; i <= D; ++i) corners[i] = r_.sites[cells[c][i]];
      centers[c] = circumcenter<D>(corners);
    }
    Layer& layer = add("voronoi", "Voronoi edges", Primitive::lines, palette::voronoi_edge, 1.5f);
    for (const auto& [a, b] : cells_sharing_a_facet<D>(cells)) {
      layer.positions.push_back(vec(centers[a]));
      layer.positions.push_back(vec(centers[b]));
    }
  }

  template <class Keep>
  Layer& poles_where(const char* id, const std::string& label, Color color, Keep keep) {
    Layer& layer = add(id, label, Primitive::points, color, D == 2 ? 7 : 4);
    const auto& poles = r_.poles.poles;
    for (int p = 0; p < static_cast<int>(poles.size()); ++p) {
      if (keep(p)) layer.positions.push_back(vec(poles[p].center));
    }
    return layer;
  }

  // The polar balls: in 2D the paper's circles, one colour; in 3D translucent spheres, the
  // inner and outer balls apart (by the labels known at this stage: at the labelling replay,
  // those given so far; before it, the final ones), at most `ball_limit` of each kind.
  void polar_balls() {
    const auto& poles = r_.poles.poles;
    const int every = std::max(1, request_.ball_every);
    // In 3D, a ball larger than the samples' box would wrap the camera in a translucent fog:
    // those (outer poles far out) are left out, the medial balls inside and near stay.
    float diagonal = 0;
    for (int c = 0; c < 3; ++c)
      diagonal += (scene_.upper[c] - scene_.lower[c]) * (scene_.upper[c] - scene_.lower[c]);
    const float largest = D == 3 ? 0.5f * std::sqrt(diagonal) : INFINITY;
    std::vector<int> shown;
    for (std::size_t p = 0; p < poles.size(); ++p) {
      // Convex poles' huge balls hide everything.
      if (!poles[p].convex && p % every == 0 && poles[p].radius <= largest) shown.push_back(int(p));
    }
    if constexpr (D == 2) {
      balls_layer("polar-balls", "polar circles", palette::polar_ball, shown);
    } else {
      const std::vector<Label> labels = labels_at_this_stage();
      std::vector<int> of_kind[3];
      for (int p : shown) of_kind[labels.empty() ? 0 : int(labels[p])].push_back(p);
      const auto translucent = [&](Color c, float share = 1) {
        return Color{c.r, c.g, c.b, share * request_.ball_opacity};
      };
      balls_layer("polar-balls", labels.empty() ? "polar balls" : "polar balls not yet labelled",
                  translucent(palette::polar_ball_3d), of_kind[int(Label::unlabelled)]);
      // Before the labelling the sides come from its end, and the legend says so.
      const std::string later = request_.stage < Stage::propagation ? " (as labelled later)" : "";
      balls_layer("inner-balls", "inner polar balls" + later, translucent(palette::inner_ball),
                  of_kind[int(Label::inner)]);
      // Fainter: the outer balls are the larger, and would hide the medial axis inside.
      balls_layer("outer-balls", "outer polar balls" + later,
                  translucent(palette::outer_ball, 0.35f), of_kind[int(Label::outer)]);
    }
  }

  std::vector<Label> labels_at_this_stage() const { return labels_at_stage(r_, request_); }

  // A layer of the balls of `poles`, thinned to `ball_limit` evenly (an empty one stays out of
  // the legend; the layer polar-balls names them all, as --layers takes it).
  void balls_layer(const char* id, const std::string& label, Color color,
                   const std::vector<int>& poles) {
    const std::size_t limit = request_.ball_limit > 0 ? std::size_t(request_.ball_limit) : 0;
    const std::size_t count = limit > 0 ? std::min(limit, poles.size()) : poles.size();
    Layer& layer = add(id,
                       label + (count < poles.size() ? " (" + std::to_string(count) + " of " +
                                                           std::to_string(poles.size()) + ")"
                                                     : ""),
                       Primitive::balls, color, 1.0f);
    layer.translucent = D == 3;  // outlines of overlapping spheres are unreadable in 3D
    for (std::size_t k = 0; k < count; ++k) {
      const auto& pole = r_.poles.poles[poles[k * poles.size() / count]];
      layer.positions.push_back(vec(pole.center));
      layer.radii.push_back(float(pole.radius));
    }
  }

  void seeds() {
    const auto& seeds = r_.seeds;
    std::vector<bool> outer(r_.poles.poles.size(), false), inner(r_.poles.poles.size(), false);
    for (int seed : seeds.outer_seeds) {
      outer[seed] = true;
      for (int partner : r_.poles.partners_of(seed)) inner[partner] = !outer[partner];
    }
    poles_where("other-poles", "other poles", palette::unlabelled_pole,
                [&](int p) { return !outer[p] && !inner[p]; });
    poles_where("inner-seeds", "inner seeds (paired with outer seeds)", palette::inner_pole,
                [&](int p) { return inner[p]; });
    poles_where("outer-seeds", "outer seeds (convex poles)", palette::convex_pole,
                [&](int p) { return outer[p]; });
  }

  void labelled_poles(const std::vector<Label>& labels, bool only_inserted) {
    std::vector<bool> inserted(labels.size(), !only_inserted);
    for (int p : r_.insertion.inserted_poles) inserted[p] = true;
    const bool bordered = r_.options.kind == Surface_kind::bordered;
    if (!only_inserted) {
      poles_where("unlabelled-poles", "unlabelled poles", palette::unlabelled_pole,
                  [&](int p) { return labels[p] == Label::unlabelled; });
    }
    poles_where("inner-poles", "inner poles", palette::inner_pole,
                [&](int p) { return labels[p] == Label::inner && (inserted[p] || !bordered); });
    poles_where("outer-poles", only_inserted ? "outer concave poles" : "outer poles",
                palette::outer_pole(D),
                [&](int p) { return labels[p] == Label::outer && inserted[p]; });
  }

  void propagation() {
    if (r_.options.method == Method::robust) {
      scene_.title = "Pole labelling by confidence (robust method)";
    }
    const auto& events = r_.propagation.events;
    const std::size_t shown =
        request_.step < 0 ? events.size() : std::min<std::size_t>(request_.step, events.size());
    std::vector<Label> labels(r_.poles.poles.size(), Label::unlabelled);
    for (std::size_t i = 0; i < shown; ++i) labels[events[i].pole] = events[i].label;
    labelled_poles(labels, /*only_inserted=*/false);
    contradicted_poles(labels, long(shown));
    if (shown == 0) return;
    // The latest event: the pole just labelled, and the ball (and cube) that labelled it.
    const Labelling_event& last = events[shown - 1];
    if (last.source >= 0) {
      const auto& source = r_.poles.poles[last.source];
      Layer& ball =
          add("source-ball", "labelling polar ball", Primitive::balls, palette::source_ball, 2.0f);
      ball.positions.push_back(vec(source.center));
      ball.radii.push_back(float(source.radius));
      if (last.reason == Label_reason::inscribed_cube) {
        Layer& cube = add("source-cube", D == 2 ? "its inscribed square" : "its inscribed cube",
                          Primitive::lines, palette::source_cube, 2.0f);
        inscribed_cube(source, cube);
      }
    }
    Layer& current = add("current-pole", "pole just labelled", Primitive::points,
                         palette::current_pole, D == 2 ? 12 : 9);
    current.positions.push_back(vec(r_.poles.poles[last.pole].center));
  }

  // Labelled poles that were offered the other label (paper: a conflict; robust: evidence at
  // least as strong as their own). Only drawn when there are some.
  // The poles offered a label against their own, up to `shown` events of the replay.
  void contradicted_poles(const std::vector<Label>& labels, long shown = -1) {
    std::vector<bool> contradicted(labels.size(), false);
    for (const auto& offer : r_.propagation.conflicts) {
      if (shown >= 0 && offer.after_events > shown) continue;
      if (labels[offer.pole] != Label::unlabelled) contradicted[offer.pole] = true;
    }
    if (std::find(contradicted.begin(), contradicted.end(), true) == contradicted.end()) return;
    const bool paper = r_.options.method == Method::paper;
    poles_where(
        "contradicted-poles",
        paper ? "poles offered both labels (conflicts)" : "poles contradicted by strong evidence",
        palette::contradicted_pole, [&](int p) { return bool(contradicted[p]); });
  }

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

  // The Voronoi cell of a sample: the Voronoi edges dual to the Delaunay facets that contain it.
  void voronoi_cell(int sample) {
    if (r_.delaunay.cells.size() != r_.delaunay.cell_count) return;
    std::vector<Cell<D>> incident;
    for (const auto& cell : r_.delaunay.cells) {
      if (std::find(cell.begin(), cell.end(), sample) != cell.end()) incident.push_back(cell);
    }
    Layer& layer =
        add("focus-cell", "the sample's Voronoi cell", Primitive::lines, palette::focus_cell, 2.5f);
    for (const auto& [a, b] : cells_sharing_a_facet<D>(incident)) {
      std::array<Point<D>, D + 1> corners_a, corners_b;
      for (int i = 0; i <= D; ++i) {
        corners_a[i] = r_.sites[incident[a][i]];
        corners_b[i] = r_.sites[incident[b][i]];
      }
      layer.positions.push_back(vec(circumcenter<D>(corners_a)));
      layer.positions.push_back(vec(circumcenter<D>(corners_b)));
    }
  }

  void focus_pole(int pole) {
    if (pole >= static_cast<int>(r_.poles.poles.size())) {
      throw std::invalid_argument("no pole " + std::to_string(pole));
    }
    const auto& p = r_.poles.poles[pole];
    Layer& ball =
        add("picked-ball", "the pole's polar ball", Primitive::balls, palette::focus_ball, 2.0f);
    ball.positions.push_back(vec(p.center));
    ball.radii.push_back(float(p.radius));
    for (const auto& event : r_.propagation.events) {
      if (event.pole != pole || event.source < 0) continue;
      Layer& source = add("picked-source", "the pole that labelled it", Primitive::points,
                          palette::convex_pole, D == 2 ? 11 : 8);
      source.positions.push_back(vec(r_.poles.poles[event.source].center));
    }
    Layer& picked =
        add("picked-pole", "picked pole", Primitive::points, palette::picked_pole, D == 2 ? 12 : 9);
    picked.positions.push_back(vec(p.center));
  }

  void focus(int sample) {
    if (sample >= n_) throw std::invalid_argument("no sample " + std::to_string(sample));
    // The sample itself, larger and darker than the others (drawn under them: a ring).
    add("picked-sample", "picked sample", Primitive::points, palette::picked_sample,
        D == 2 ? 14 : 11)
        .positions.push_back(vec(r_.sites[sample]));
    voronoi_cell(sample);
    Layer& balls =
        add("focus-balls", "the sample's polar balls", Primitive::balls, palette::focus_ball, 2.0f);
    Layer& cubes = add("focus-cubes", D == 2 ? "inscribed squares" : "inscribed cubes",
                       Primitive::lines, palette::inscribed_cube, 2.0f);
    Layer& poles = add("focus-poles", "the sample's poles", Primitive::points, palette::picked_pole,
                       D == 2 ? 10 : 8);
    for (int pole : {r_.poles.positive_pole[sample], r_.poles.negative_pole[sample]}) {
      if (pole < 0) continue;
      const auto& p = r_.poles.poles[pole];
      balls.positions.push_back(vec(p.center));
      balls.radii.push_back(float(p.radius));
      inscribed_cube(p, cubes);
      poles.positions.push_back(vec(p.center));
    }
  }

  // The all-sample cells of DT(S ∪ BBV) fill the samples' convex hull: what the sculpting
  // starts from before any pole is inserted (the paper's Fig. 1a and 2a).
  void hull() {
    require_cells(r_.delaunay);
    std::vector<Cell<D>> cells;
    for (const auto& cell : r_.delaunay.cells) {
      if (std::all_of(cell.begin(), cell.end(), [&](int v) { return v < n_; }))
        cells.push_back(cell);
    }
    if constexpr (D == 2) {
      Layer& layer = add("hull", "convex hull (all-sample triangles)", Primitive::triangles,
                         palette::solid, 1.0f);
      for (const auto& cell : cells) {
        for (int v : cell) layer.positions.push_back(vec(r_.sites[v]));
      }
      edges_of(cells, "hull-edges", "their edges", palette::delaunay_edge);
    } else {
      // Its boundary: the facets of one all-sample cell only, facing out.
      std::vector<std::pair<std::array<int, 3>, std::array<int, 3>>> facets;  // sorted, oriented
      for (const auto& cell : cells) {
        for (const auto& f : Facet_orientation<3>::vertex) {
          std::array<int, 3> oriented{cell[f[0]], cell[f[1]], cell[f[2]]}, key = oriented;
          std::sort(key.begin(), key.end());
          facets.emplace_back(key, oriented);
        }
      }
      std::sort(facets.begin(), facets.end());
      Layer& layer = add("hull", "convex hull", Primitive::triangles, palette::surface, 1.0f);
      layer.lit = true;
      for (std::size_t i = 0; i < facets.size(); ++i) {
        const bool shared = (i + 1 < facets.size() && facets[i + 1].first == facets[i].first) ||
                            (i > 0 && facets[i - 1].first == facets[i].first);
        if (shared) continue;
        for (int v : facets[i].second) layer.positions.push_back(vec(r_.sites[v]));
      }
    }
  }

  // The hull's cells that the method removed: the all-sample cells of stage 1 not in the solid
  // (Kuo & Yau's Figs. 1 and 2: what sculpting takes away). Only for the methods whose solid is
  // made of those cells, and when the triangulation was kept.
  std::vector<Cell<D>> sculpted_away() const {
    const Method m = r_.options.method;
    const bool carves_the_hull = sculpts(m) || m == Method::boissonnat || m == Method::tight_cocone;
    if (!carves_the_hull || r_.delaunay.cells.size() != r_.delaunay.cell_count) return {};
    std::vector<Cell<D>> kept = r_.solid;
    for (auto& cell : kept) std::sort(cell.begin(), cell.end());
    std::sort(kept.begin(), kept.end());
    std::vector<Cell<D>> removed;
    for (const auto& cell : r_.delaunay.cells) {
      if (std::any_of(cell.begin(), cell.end(), [&](int v) { return v >= n_; })) continue;
      auto sorted = cell;
      std::sort(sorted.begin(), sorted.end());
      if (!std::binary_search(kept.begin(), kept.end(), sorted)) removed.push_back(cell);
    }
    return removed;
  }

  void solid() {
    const std::vector<Cell<D>> removed = sculpted_away();
    if constexpr (D == 2) {
      Layer& layer = add("solid", "sculpted solid (all-sample triangles)", Primitive::triangles,
                         palette::solid, 1.0f);
      for (const auto& cell : r_.solid) {
        for (int v : cell) layer.positions.push_back(vec(r_.sites[v]));
      }
      if (!removed.empty()) {
        Layer& away =
            add("sculpted-away", "sculpted away (" + std::to_string(removed.size()) + " triangles)",
                Primitive::triangles, palette::sculpted_away, 1.0f);
        for (const auto& cell : removed) {
          for (int v : cell) away.positions.push_back(vec(r_.sites[v]));
        }
      }
    } else {
      solid_cut_through_whole_cells(removed);
    }
  }

  // The solid and what was sculpted away, cut at a plane through whole cells: the user's clip,
  // or else the middle of the box across z with the half towards the default camera cut away,
  // so that the inside shows. The title says which (no half is ever hidden unsaid).
  void solid_cut_through_whole_cells(const std::vector<Cell<D>>& removed) {
    const bool alpha = r_.options.method == Method::alpha_shape;
    const bool tight = r_.options.method == Method::tight_cocone;
    if (r_.options.method == Method::boissonnat)
      scene_.title = "Boissonnat: the cells left when every sample is on the boundary";
    if (alpha) scene_.title = "Alpha solid: the cells of circumradius below alpha";
    if (tight) scene_.title = "Tight co-cone: the cells left after peeling";
    const std::string label = alpha   ? "alpha solid (tetrahedra)"
                              : tight ? "cells not peeled (tetrahedra)"
                                      : "sculpted solid (all-sample tetrahedra)";
    cut_through_whole_cells(
        {"solid", label, palette::solid, &r_.solid},
        {"sculpted-away", "sculpted away (" + std::to_string(removed.size()) + " tetrahedra)",
         palette::sculpted_away, &removed});
  }

  // The user's clip, or else the middle of the box across z; the title says which.
  void cut_through_whole_cells(const Whole_cells& solid, const Whole_cells& removed) {
    Clip middle;
    middle.elevation = 90;  // the normal +z: the upper half goes
    const Clip& clip = request_.clipped ? request_.clip : middle;
    scene_.title += request_.clipped ? "; whole cells, cut at the clip plane"
                                     : "; whole cells, those above mid z cut away";
    whole_cells_cut(layers_, r_.sites, plane_of(scene_, clip), clip.slab, solid, removed,
                    requested("cut-cells"));
  }

  // The sculpting replayed (carving_replay.hpp): the hull's cells still there, those taken away
  // so far, and those the step shown takes away, with the pole that destroyed them (paper).
  void carving() {
    if (!carves_cells(r_.options.method, r_.options.kind, D)) {
      scene_.title = "No cells carved: open curves join each sample to its nearest neighbours";
      return;
    }
    const auto held = shared_carving_replay(r_);
    const Carving_replay& replay = *held;
    const Carving_moment moment = moment_of(replay, r_.delaunay.cells.size(), request_.step);
    const std::size_t shown = moment.shown;
    std::vector<Cell<D>> kept, away, just;
    for (int c : replay.hull) {
      const Cell_state state = moment.states[c];
      (state == Cell_state::kept           ? kept
       : state == Cell_state::taken_before ? away
                                           : just)
          .push_back(r_.delaunay.cells[c]);
    }
    const char* method = r_.options.method == Method::boissonnat ? "Boissonnat"
                         : replay.by_poles                       ? "Sculpting"
                                                                 : "Carving";
    scene_.title = std::string(method) + ", " +
                   (shown == 0 ? "before any cell leaves: the hull's " +
                                     std::to_string(replay.hull.size()) + " cells"
                               : describe_step(replay, shown - 1, D, r_.carving));
    const auto cells = [](std::size_t count) {
      return "(" + std::to_string(count) +
             (count == 1 ? (D == 2 ? " triangle)" : " tetrahedron)")
                         : (D == 2 ? " triangles)" : " tetrahedra)"));
    };
    const std::string kept_label = "the hull's cells still there " + cells(kept.size()),
                      away_label = "taken away before " + cells(away.size()),
                      just_label = "taken away at this step " + cells(just.size());
    if constexpr (D == 2) {
      const auto fill = [&](const std::vector<Cell<D>>& set, const char* id,
                            const std::string& label, Color colour) {
        if (set.empty()) return;
        Layer& layer = add(id, label, Primitive::triangles, colour, 1.0f);
        for (const auto& cell : set) {
          for (int v : cell) layer.positions.push_back(vec(r_.sites[v]));
        }
      };
      fill(kept, "solid", kept_label, palette::solid);
      fill(away, "sculpted-away", away_label, palette::sculpted_away);
      fill(just, "just-removed", just_label, palette::just_removed);
      // Their circumcircles: each holds the pole inserted (paper), or an outer pole (robust).
      if (!just.empty() && just.size() <= 50) {
        Layer& circles = add("just-removed-circles",
                             just.size() == 1 ? "its circumcircle" : "their circumcircles",
                             Primitive::balls, palette::carving_circle, 2.0f);
        for (const auto& cell : just) {
          std::array<Point<D>, D + 1> corners;
          for (int i = 0; i <= D; ++i) corners[i] = r_.sites[cell[i]];
          const Point<D> centre = circumcenter<D>(corners);
          circles.positions.push_back(vec(centre));
          circles.radii.push_back(
              float(std::hypot(centre[0] - corners[0][0], centre[1] - corners[0][1])));
        }
      }
    } else {
      if (request_.clipped) {
        // Cut at the user's plane: what was taken away shows beside what is left.
        std::vector<Cell<D>> before = away;
        before.insert(before.end(), just.begin(), just.end());
        cut_through_whole_cells({"solid", kept_label, palette::solid, &kept},
                                {"sculpted-away", away_label, palette::sculpted_away, &before});
      } else {
        // Seen whole, the hull shrinks towards the solid; what left would only hide it.
        scene_.title += "; the cells left, seen whole";
        Clip everything;
        everything.position = 1;
        const std::vector<Cell<D>> none;
        whole_cells_cut(layers_, r_.sites, plane_of(scene_, everything), 0,
                        {"solid", kept_label, palette::solid, &kept},
                        {"sculpted-away", away_label, palette::sculpted_away, &none}, false);
      }
      // What leaves at this step, whole wherever it lies: the eye finds the step there.
      if (!just.empty()) {
        Layer& layer =
            add("just-removed", just_label, Primitive::triangles, palette::just_removed, 1.0f);
        layer.lit = true;
        layer.cut = true;
        for (const auto& cell : just) {
          for (const auto& f : Facet_orientation<3>::vertex) {
            for (int i : f) layer.positions.push_back(vec(r_.sites[cell[i]]));
          }
        }
      }
    }
    // An outer pole, in its colour: the step's story is the cells, so no other pole is drawn.
    if (shown > 0 && replay.steps[shown - 1].pole >= 0) {
      Layer& pole = add("current-pole", "pole just inserted", Primitive::points,
                        palette::outer_pole(D), D == 2 ? 12 : 9);
      pole.positions.push_back(vec(r_.poles.poles[replay.steps[shown - 1].pole].center));
    }
  }

  void surface() {
    // The samples, or the vertices of a result that does not interpolate (the power crust).
    const auto& points = r_.surface_points();
    if constexpr (D == 2) {
      Layer& layer = add("curve", "reconstructed curve", Primitive::lines, palette::curve, 3.0f);
      for (const auto& edge : r_.surface) {
        layer.positions.push_back(vec(points[edge[0]]));
        layer.positions.push_back(vec(points[edge[1]]));
      }
      borders_and_defects();
    } else {
      Layer& layer =
          add("surface", "reconstructed surface", Primitive::triangles, palette::surface, 1.0f);
      layer.lit = true;
      for (const auto& t : r_.surface) {
        for (int v : t) layer.positions.push_back(vec(points[v]));
      }
      if (request_.smooth)
        layer.normals = vertex_normals(points, r_.surface, static_cast<int>(points.size()));
      borders_and_defects();
      openings();
      if (request_.wireframe) {
        Layer& wire = add("wireframe", "edges", Primitive::lines, palette::wireframe, 1.0f);
        wire.in_legend = false;
        wire.scales = false;
        for (const auto& t : r_.surface) {
          for (int j = 0; j < 3; ++j) {
            wire.positions.push_back(vec(points[t[j]]));
            wire.positions.push_back(vec(points[t[(j + 1) % 3]]));
          }
        }
      }
    }
  }

  // The crust's DT(S ∪ V): its edges, and the Voronoi vertices V that break the edges across
  // the region between two parts of the curve.
  void crust_delaunay() {
    const auto& crust = r_.crust;
    if (crust.delaunay.cells.size() != crust.delaunay.cell_count) {
      throw std::invalid_argument("this reconstruction did not keep its triangulations");
    }
    edges_of(crust.delaunay.cells, "crust-delaunay", "Delaunay edges DT(S + V)",
             palette::delaunay_edge,
             [&](int i) { return i < n_ ? r_.sites[i] : crust.voronoi_vertices[i - n_]; });
    if (D == 3) scene_.title = "DT(S + P): the samples and their poles";
    // Red like the poles, which are some of them: both lie near the medial axis.
    Layer& vertices = add("voronoi-vertices", D == 2 ? "Voronoi vertices V" : "poles P",
                          Primitive::points, palette::pole, D == 2 ? 6 : 4);
    for (const auto& v : crust.voronoi_vertices) vertices.positions.push_back(vec(v));
  }

  // The triangles a filtering method chose (shaded) and those the pruning removed (red edges):
  // the surface is the outer boundary of the shaded ones.
  // The candidates, and those pruned: all of them, or (a replay) the first `step` in the order
  // the pruning took them, the last of those lit.
  void candidates() {
    const auto& candidates = r_.candidates;
    const std::size_t shown = request_.step < 0
                                  ? candidates.pruned.size()
                                  : std::min<std::size_t>(request_.step, candidates.pruned.size());
    if (shown < candidates.pruned.size())
      scene_.title +=
          ", pruned " + std::to_string(shown) + " of " + std::to_string(candidates.pruned.size());
    Layer& kept = add("candidates",
                      "candidates kept (" + std::to_string(candidates.chosen.size() - shown) + ")",
                      Primitive::triangles, palette::solid, 1.0f);
    kept.lit = true;
    std::vector<Facet<D>> pruned(candidates.pruned.begin(),
                                 candidates.pruned.begin() + long(shown));
    for (auto& f : pruned) std::sort(f.begin(), f.end());
    std::sort(pruned.begin(), pruned.end());
    for (const auto& facet : candidates.chosen) {
      auto sorted = facet;
      std::sort(sorted.begin(), sorted.end());
      if (std::binary_search(pruned.begin(), pruned.end(), sorted)) continue;
      for (int v : facet) kept.positions.push_back(vec(r_.sites[v]));
    }
    if (shown > 0) {
      Layer& removed =
          add("pruned",
              std::string(candidates.rims_kept ? "pruned, rims of holes kept (" : "pruned (") +
                  std::to_string(shown) + ")",
              Primitive::lines, palette::non_manifold, 2.0f);
      for (std::size_t i = 0; i < shown; ++i) {
        const auto& facet = candidates.pruned[i];
        for (int j = 0; j < D; ++j) {
          removed.positions.push_back(vec(r_.sites[facet[j]]));
          removed.positions.push_back(vec(r_.sites[facet[(j + 1) % D]]));
        }
      }
    }
    // During the replay, the triangle the step prunes, filled where the eye must go.
    if (request_.step > 0 && shown > 0) {
      Layer& now = add("just-removed", "pruned at this step", Primitive::triangles,
                       palette::just_removed, 1.0f);
      for (int v : candidates.pruned[shown - 1]) now.positions.push_back(vec(r_.sites[v]));
    }
    // The samples the co-cone does not trust, and those the tight co-cone found no umbrella at.
    const auto marked = [&](const char* id, const std::string& title,
                            const std::vector<int>& samples, Color color) {
      if (samples.empty()) return;
      Layer& layer = add(id, title + " (" + std::to_string(samples.size()) + ")", Primitive::points,
                         color, 7.0f);
      for (int s : samples) layer.positions.push_back(vec(r_.sites[s]));
    };
    marked("undersampled", "undersampled samples", candidates.undersampled, palette::undersampled);
    marked("without-umbrella", "samples without umbrella", candidates.without_umbrella,
           palette::without_umbrella);
  }

  // The triangles the robust bordered rule removed as spanning an opening, as edges: the caps
  // the closed rules would have put over the openings (methods/robust/bordered_surface.hpp).
  void openings() {
    const auto& spanning = r_.candidates.spanning;
    if (spanning.empty()) return;
    Layer& layer =
        add("openings", "removed over openings (" + std::to_string(spanning.size()) + ")",
            Primitive::lines, palette::opening, 1.0f);
    for (const auto& facet : spanning) {
      for (int j = 0; j < D; ++j) {
        layer.positions.push_back(vec(r_.sites[facet[j]]));
        layer.positions.push_back(vec(r_.sites[facet[(j + 1) % D]]));
      }
    }
  }

  // The result's border (curve ends in 2D, border edges in 3D) and its non-manifold ridges
  // (branching samples, edges on more than two triangles), each a layer when there are any.
  void borders_and_defects() {
    std::map<std::array<int, D - 1>, int> facets_on;
    for (const auto& facet : r_.surface) {
      for (int skip = 0; skip < D; ++skip) {
        std::array<int, D - 1> ridge;
        for (int j = 0, k = 0; j < D; ++j) {
          if (j != skip) ridge[k++] = facet[j];
        }
        std::sort(ridge.begin(), ridge.end());
        ++facets_on[ridge];
      }
    }
    const auto layer_of = [&](bool border) -> Layer* {
      std::size_t count = 0;
      for (const auto& [ridge, facets] : facets_on) count += border ? facets == 1 : facets > 2;
      if (count == 0) return nullptr;
      const std::size_t loops = r_.stats.boundary_loops;
      // Loops noise tore in the sheet and loops too short to be an opening's rim: not openings
      // (robust bordered rule).
      std::string not_openings;
      if (r_.stats.torn_loops > 0) not_openings = std::to_string(r_.stats.torn_loops) + " torn";
      if (r_.stats.short_loops > 0) {
        not_openings +=
            (not_openings.empty() ? "" : ", ") + std::to_string(r_.stats.short_loops) + " short";
      }
      const std::string torn = not_openings.empty() ? "" : " (" + not_openings + ")";
      const std::string what =
          D == 2
              ? (border ? "curve ends (" + std::to_string(count) + ")"
                        : "branching samples (" + std::to_string(count) + ")")
              : (border ? "border: " + std::to_string(loops) + (loops == 1 ? " loop" : " loops") +
                              torn + ", " + std::to_string(count) + " edges"
                        : "non-manifold edges (" + std::to_string(count) + ")");
      return &add(border ? "border" : "non-manifold", what,
                  D == 2 ? Primitive::points : Primitive::lines,
                  border ? palette::border : palette::non_manifold, D == 2 ? 11.0f : 3.0f);
    };
    for (const bool border : {true, false}) {
      Layer* layer = layer_of(border);
      if (!layer) continue;
      for (const auto& [ridge, facets] : facets_on) {
        if (border ? facets != 1 : facets <= 2) continue;
        for (int v : ridge) layer->positions.push_back(vec(r_.surface_points()[v]));
      }
    }
    unused_samples();
    add_handle_layers(layers_, r_);
  }

  // The samples the result leaves out: an interpolating reconstruction should pass through
  // every one, so each left off marks a place it went wrong (a valley cut across, a cavity).
  void unused_samples() {
    if (!r_.interpolates()) return;  // vertices of its own: no sample is on it
    std::vector<bool> used(n_, false);
    for (const auto& facet : r_.surface) {
      for (int v : facet) {
        if (v < n_) used[v] = true;
      }
    }
    const auto unused = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
    if (unused == 0) return;
    Layer& layer = add("unused-samples", "samples left off (" + std::to_string(unused) + ")",
                       Primitive::points, palette::unused_sample, D == 2 ? 10.0f : 7.0f);
    for (int i = 0; i < n_; ++i) {
      if (!used[i]) layer.positions.push_back(vec(r_.sites[i]));
    }
  }

  void select_layers() {
    if (request_.layers.empty()) return;
    for (const auto& id : request_.layers) {
      const bool known = std::any_of(scene_.layers.begin(), scene_.layers.end(),
                                     [&](const Layer& l) { return l.id == id; });
      if (!known) {
        std::string ids;
        for (const auto& l : scene_.layers) ids += (ids.empty() ? "" : ", ") + l.id;
        throw std::invalid_argument("the stage " + std::string(stage_id(request_.stage)) +
                                    " has no layer '" + id + "' (it has: " + ids + ")");
      }
    }
    // The layer polar-balls stands for every polar ball, inner and outer ones too.
    std::vector<std::string> ids = request_.layers;
    if (requested("polar-balls")) ids.insert(ids.end(), {"inner-balls", "outer-balls"});
    std::vector<Layer> kept;
    for (auto& layer : scene_.layers) {
      if (std::find(ids.begin(), ids.end(), layer.id) != ids.end())
        kept.push_back(std::move(layer));
    }
    scene_.layers = std::move(kept);
  }

  const Reconstruction<D>& r_;
  const Request& request_;
  const int n_;
  Scene scene_;
  std::deque<Layer> layers_;
};

}  // namespace

Scene build_scene(const Reconstruction<2>& reconstruction, const Request& request) {
  Scene scene = Scene_builder<2>(reconstruction, request).build();
  if (request.colour_blind) recolour(scene, Colours::colour_blind);
  return scene;
}

Scene build_scene(const Reconstruction<3>& reconstruction, const Request& request) {
  Scene scene = request.sectioned ? build_section(reconstruction, request)
                                  : Scene_builder<3>(reconstruction, request).build();
  if (request.clipped && !request.sectioned) clip(scene, request.clip);
  if (request.colour_blind) recolour(scene, Colours::colour_blind);
  return scene;
}

std::vector<std::string> layer_ids(const Scene& scene) {
  std::vector<std::string> ids;
  for (const auto& layer : scene.layers) ids.push_back(layer.id);
  return ids;
}

}  // namespace sculpt::scene
