// SPDX-License-Identifier: GPL-3.0-or-later
// Turns a stage of a reconstruction into layers. One builder serves both dimensions: 2D
// positions get z = 0, and the few differences (cube or square, circle or sphere) follow D.
// The poles, the candidates and the result are drawn by headers of their own (pole_layers.hpp,
// candidate_layers.hpp, result_layers.hpp), given the builder's state as one Builder_context.
#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "builder_context.hpp"
#include "candidate_layers.hpp"
#include "carving_replay.hpp"
#include "cleaning_layers.hpp"
#include "clipping.hpp"
#include "colours.hpp"
#include "core/facet_orientation.hpp"
#include "cut_cells.hpp"
#include "growth_stages.hpp"
#include "layer_helpers.hpp"
#include "palette.hpp"
#include "pole_layers.hpp"
#include "result_layers.hpp"
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
    const Builder_context<D> ctx{r_, request_, scene_, layers_, n_};
    switch (request_.stage) {
      case Stage::samples:
        add_cleaning_layers(ctx);
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
        voronoi_edges(ctx);
        break;
      case Stage::poles:
        // Thousands of spheres hide everything in 3D: there they are shown only when asked for.
        if (D == 2 || wants_polar_balls()) polar_balls(ctx);
        poles_where(ctx, "poles", "poles", palette::pole, [](int) { return true; });
        break;
      case Stage::seeds:
        seeds(ctx);
        break;
      case Stage::propagation:
        propagation(ctx);
        break;
      case Stage::outer_concave:
        labelled_poles(ctx, r_.propagation.labels,
                       /*only_inserted=*/r_.options.method == Method::paper);
        contradicted_poles(ctx, r_.propagation.labels);
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
          labelled_poles(ctx, r_.propagation.labels, /*only_inserted=*/false);
          break;
        }
        // Without the triangulations kept, the solid was read off the first DT by queries and
        // DT(S + OUP) never built.
        if (!r_.options.keep_triangulations) throw std::invalid_argument(triangulations_not_kept);
        require_cells(r_.sculpted_delaunay);
        edges_of(r_.sculpted_delaunay.cells, "sculpted-delaunay", "Delaunay edges DT(S + OUP)",
                 palette::delaunay_edge);
        labelled_poles(ctx, r_.propagation.labels, /*only_inserted=*/true);
        break;
      case Stage::crust_delaunay:
        crust_delaunay();
        break;
      case Stage::candidates:
        candidates(ctx);
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
        surface(ctx);
        break;
    }
    if (request_.stage != Stage::poles && wants_polar_balls()) polar_balls(ctx);
    if (request_.focus_sample >= 0) focus(ctx, request_.focus_sample);
    if (request_.focus_pole >= 0) focus_pole(ctx, request_.focus_pole);
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
