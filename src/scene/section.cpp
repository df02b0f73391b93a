// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <stdexcept>

#include "scene/carving_replay.hpp"
#include "scene/layer_helpers.hpp"
#include "scene/palette.hpp"
#include "scene/simplex_geometry.hpp"

namespace sculpt::scene {
namespace {

Vec3 along(const Vec3& p, const Vec3& q, float t) {
  return {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])};
}

// Where the segment pq crosses the plane (p and q on opposite sides).
Vec3 crossing(const Vec3& p, const Vec3& q, float side_p, float side_q) {
  return along(p, q, side_p / (side_p - side_q));
}

float distance(const Vec3& p, const Vec3& q) {
  return std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
}

// The area of the triangles [begin, end), three corners each.
float area(std::vector<Vec3>::const_iterator begin, std::vector<Vec3>::const_iterator end) {
  float total = 0;
  for (auto t = begin; end - t >= 3; t += 3) {
    const Vec3 &a = t[0], &b = t[1], &c = t[2];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    total += 0.5f * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                               u[0] * v[1] - u[1] * v[0]);
  }
  return total;
}

}  // namespace

void cut_tetrahedron(const std::array<Vec3, 4>& corners, const Clip_plane& plane,
                     std::vector<Vec3>& fill, std::vector<Vec3>& outline) {
  float side[4];
  std::vector<int> before, beyond;
  for (int i = 0; i < 4; ++i) {
    side[i] = plane.side(corners[i]);
    (side[i] <= 0 ? before : beyond).push_back(i);
  }
  if (before.empty() || beyond.empty()) return;
  const auto cut = [&](int i, int j) { return crossing(corners[i], corners[j], side[i], side[j]); };
  std::vector<Vec3> polygon;  // in order around the cut
  if (before.size() == 2) {
    // Two corners each side: the edges a-c, a-d, b-d, b-c cross, in that order around.
    const int a = before[0], b = before[1], c = beyond[0], d = beyond[1];
    polygon = {cut(a, c), cut(a, d), cut(b, d), cut(b, c)};
  } else {
    // One corner alone on its side: the three edges from it cross.
    const int lone = before.size() == 1 ? before[0] : beyond[0];
    for (int other = 0; other < 4; ++other) {
      if (other != lone) polygon.push_back(cut(lone, other));
    }
  }
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    fill.insert(fill.end(), {polygon[0], polygon[k], polygon[k + 1]});
  for (std::size_t k = 0; k < polygon.size(); ++k)
    outline.insert(outline.end(), {polygon[k], polygon[(k + 1) % polygon.size()]});
}

void cut_triangle(const std::array<Vec3, 3>& corners, const Clip_plane& plane,
                  std::vector<Vec3>& segments) {
  float side[3];
  for (int i = 0; i < 3; ++i) side[i] = plane.side(corners[i]);
  std::vector<Vec3> ends;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if ((side[i] <= 0) != (side[j] <= 0))
      ends.push_back(crossing(corners[i], corners[j], side[i], side[j]));
  }
  if (ends.size() == 2) segments.insert(segments.end(), {ends[0], ends[1]});
}

namespace {

class Section_builder {
 public:
  Section_builder(const Reconstruction<3>& r, const Request& request)
      : r_(r), request_(request), n_(int(r.sample_count())) {
    scene_.dimension = 3;
    scene_.lower = scene_.upper = vec(r.sites[0]);
    for (int s = 0; s < n_; ++s) {
      const Vec3 p = vec(r.sites[s]);
      for (int k = 0; k < 3; ++k) {
        scene_.lower[k] = std::min(scene_.lower[k], p[k]);
        scene_.upper[k] = std::max(scene_.upper[k], p[k]);
      }
    }
    plane_ = plane_of(scene_, request.clip);
    scene_.seen_along = true;
    scene_.along = plane_.normal;
    // Lines and points are lifted a hair towards the viewer (who looks along the normal), so
    // that the fill under them does not hide them.
    lift_ = 1e-3f * plane_.extent;
    // The samples near the plane: within about a sample spacing of it (a surface of n samples
    // in a box of this size has them about extent / sqrt(n) apart).
    band_ = 1.5f * plane_.extent / std::sqrt(float(std::max(n_, 1)));
  }

  Scene build() {
    const Method method = r_.options.method;
    require_stage(method, 3, request_.stage);
    switch (request_.stage) {
      case Stage::delaunay:
      case Stage::hull:
        require(r_.delaunay);
        scene_.title = "Section of DT(S + BBV)";
        cells_by_kind(r_.delaunay.cells,
                      [&](const Cell<3>& cell) { return all_samples(cell) ? 0 : 2; });
        break;
      case Stage::voronoi:
        require(r_.delaunay);
        scene_.title = "Section of the Voronoi diagram";
        voronoi();
        break;
      case Stage::sculpted_delaunay:
        if (inserts_poles(method, r_.options.kind, 3)) {
          require(r_.sculpted_delaunay);
          scene_.title = "Section of DT(S + OUP): the cells with a pole go";
          cells_by_kind(r_.sculpted_delaunay.cells, [&](const Cell<3>& cell) {
            if (std::any_of(cell.begin(), cell.end(), [&](int v) { return v >= n_ && v < n_ + 8; }))
              return 2;
            return all_samples(cell) ? 0 : 1;
          });
          break;
        }
        [[fallthrough]];
      case Stage::solid: {
        require(r_.delaunay);
        scene_.title =
            sculpts(method) || method == Method::boissonnat || method == Method::tight_cocone
                ? "Section of the solid and what was sculpted away"
                : "Section of the solid and the hull's other cells";
        std::vector<Cell<3>> kept = r_.solid;
        for (auto& cell : kept) std::sort(cell.begin(), cell.end());
        std::sort(kept.begin(), kept.end());
        cells_by_kind(r_.delaunay.cells, [&](const Cell<3>& cell) {
          if (!all_samples(cell)) return 2;
          auto sorted = cell;
          std::sort(sorted.begin(), sorted.end());
          return std::binary_search(kept.begin(), kept.end(), sorted) ? 0 : 1;
        });
        break;
      }
      case Stage::carving:
        carving();
        break;
      case Stage::crust_delaunay: {
        require(r_.crust.delaunay);
        scene_.title = "Section of DT(S + P): the samples and their poles";
        position_ = [this](int i) {
          return i < n_ ? r_.sites[i] : r_.crust.voronoi_vertices[i - n_];
        };
        cells_by_kind(r_.crust.delaunay.cells,
                      [&](const Cell<3>& cell) { return all_samples(cell) ? 0 : 2; });
        break;
      }
      case Stage::surface:
        scene_.title = "Section of the surface";
        surface();
        break;
      default:
        scene_.title = std::string(stage_title(request_.stage)) + ", near the plane";
        break;
    }
    if (request_.polar_balls || asked("polar-balls") || asked("inner-balls") ||
        asked("outer-balls"))
      polar_circles();
    // The carving's story is the cells and the pole inserted: no other pole is drawn.
    if (request_.stage != Stage::carving) poles_near_the_plane();
    samples_near_the_plane();
    for (auto& layer : layers_) {
      layer.cut = true;  // already at the plane: no cut-away after
      // The layer polar-balls stands for every polar ball, inner and outer ones too.
      const bool ball = layer.id == "inner-balls" || layer.id == "outer-balls";
      if (request_.layers.empty() || asked(layer.id.c_str()) || (ball && asked("polar-balls")))
        scene_.layers.push_back(std::move(layer));
    }
    return std::move(scene_);
  }

 private:
  static constexpr const char* not_kept =
      "this section needs the triangulations, which the reconstruction did not keep "
      "(keep_triangulations)";

  void require(const Delaunay_stage<3>& stage) const {
    if (stage.cells.size() != stage.cell_count) throw std::invalid_argument(not_kept);
  }

  bool asked(const char* id) const {
    return std::find(request_.layers.begin(), request_.layers.end(), id) != request_.layers.end();
  }

  bool all_samples(const Cell<3>& cell) const {
    return std::all_of(cell.begin(), cell.end(), [&](int v) { return v < n_; });
  }

  Layer& add(const char* id, const std::string& label, Primitive primitive, Color color,
             float size) {
    return add_layer(layers_, id, label, primitive, color, size);
  }

  Vec3 lifted(const Vec3& p, float times = 1) const {
    return {p[0] + times * lift_ * plane_.normal[0], p[1] + times * lift_ * plane_.normal[1],
            p[2] + times * lift_ * plane_.normal[2]};
  }

  Vec3 on_plane(const Vec3& p) const {
    const float side = plane_.side(p);
    return lifted({p[0] - side * plane_.normal[0], p[1] - side * plane_.normal[1],
                   p[2] - side * plane_.normal[2]},
                  2);
  }

  // The carving replay at its step (carving_replay.hpp): the hull's cells still there, those
  // taken away before, those the step takes away.
  void carving() {
    require(r_.delaunay);
    if (!carves_cells(r_.options.method, r_.options.kind, 3)) {
      scene_.title = "No cells carved";
      return;
    }
    const auto held = shared_carving_replay(r_);
    const Carving_replay& replay = *held;
    const Carving_moment moment = moment_of(replay, r_.delaunay.cells.size(), request_.step);
    const std::size_t shown = moment.shown;
    // The kinds cells_by_kind fills: 0 kept, 1 taken before, 2 outside the hull, 3 taken now.
    const auto kind_of = [](Cell_state state) {
      switch (state) {
        case Cell_state::kept:
          return 0;
        case Cell_state::taken_before:
          return 1;
        case Cell_state::taken_now:
          return 3;
        default:
          return 2;
      }
    };
    scene_.title =
        "Section of the carving, " + (shown == 0 ? std::string("before any cell leaves")
                                                 : describe_step(replay, shown - 1, 3, r_.carving));
    const Cell<3>* first = r_.delaunay.cells.data();
    cells_by_kind(r_.delaunay.cells,
                  [&](const Cell<3>& cell) { return kind_of(moment.states[&cell - first]); });
    if (shown > 0 && replay.steps[shown - 1].pole >= 0) {
      Layer& pole =
          add("current-pole", "pole just inserted", Primitive::points, palette::outer_pole_3d, 9);
      pole.positions.push_back(on_plane(vec(r_.poles.poles[replay.steps[shown - 1].pole].center)));
    }
  }

  // The cut of every cell, filled by its kind: 0 inside (the hull's or the solid's), 1 sculpted
  // away, 2 outside (a box corner or an inserted pole among its corners), 3 taken away at the
  // carving replay's step.
  template <class Kind>
  void cells_by_kind(const std::vector<Cell<3>>& cells, Kind kind) {
    std::vector<Vec3> fill[4], outline;
    float sides_in_hull = 0, area_in_hull = 0;  // of the cells of the hull: kinds 0 and 1
    for (const auto& cell : cells) {
      std::array<Vec3, 4> corners;
      for (int i = 0; i < 4; ++i) corners[i] = vec(position_(cell[i]));
      const int k = kind(cell);
      const std::size_t filled = fill[k].size(), drawn = outline.size();
      cut_tetrahedron(corners, plane_, fill[k], outline);
      if (k == 2) continue;
      area_in_hull += area(fill[k].begin() + long(filled), fill[k].end());
      for (std::size_t p = drawn; p + 1 < outline.size(); p += 2)
        sides_in_hull += distance(outline[p], outline[p + 1]);
    }
    const bool sculpting = request_.stage == Stage::solid ||
                           request_.stage == Stage::sculpted_delaunay ||
                           request_.stage == Stage::carving;
    // The alpha shape keeps cells without carving the hull: the others are not sculpted away.
    const Method m = r_.options.method;
    const bool carves = sculpts(m) || m == Method::boissonnat || m == Method::tight_cocone;
    const bool crust = request_.stage == Stage::crust_delaunay;
    const char* labels[4] = {sculpting ? "cells kept (cut)"
                             : crust   ? "cells of samples only (cut)"
                                       : "cells of the hull (cut)",
                             carves ? "cells sculpted away (cut)" : "cells not in the solid (cut)",
                             crust ? "cells with a pole (cut)" : "cells with a box corner (cut)",
                             "cells taken away at this step (cut)"};
    const char* ids[4] = {"section-inside", "section-away", "section-outside",
                          "section-just-removed"};
    const Color colours[4] = {palette::solid, palette::sculpted_away, palette::section_outside,
                              palette::just_removed};
    for (int k = 0; k < 4; ++k) {
      if (fill[k].empty()) continue;
      add(ids[k], labels[k], Primitive::triangles, colours[k], 1.0f).positions = std::move(fill[k]);
    }
    // The cells' sides tell the cells apart, unless a plane along a thin part cuts a crowd of
    // slivers whose sides, a pixel wide, would cover the hull's fill in grey (in a picture of
    // about 800 pixels across the box): then they are drawn only when asked for.
    const float pixel = plane_.extent / 800;
    const bool crowded = sides_in_hull * pixel > 0.4f * area_in_hull;
    if (crowded && !asked("section-edges")) return;
    Layer& edges = add("section-edges", "the cells' sides on the plane", Primitive::lines,
                       palette::section_edge, 1.0f);
    for (const auto& p : outline) edges.positions.push_back(lifted(p));
  }

  // A Voronoi edge (dual of the facet two cells share) crosses the plane at a point that lies on
  // the faces dual to the facet's three edges; a face crossed twice is cut along a segment.
  void voronoi() {
    const auto& cells = r_.delaunay.cells;
    std::vector<Vec3> centres(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      std::array<Point<3>, 4> corners;
      for (int i = 0; i < 4; ++i) corners[i] = r_.sites[cells[c][i]];
      centres[c] = vec(circumcenter<3>(corners));
    }
    std::map<std::pair<int, int>, std::vector<Vec3>> crossings;  // Delaunay edge -> points
    for (const auto& [a, b] : cells_sharing_a_facet<3>(cells)) {
      const float sa = plane_.side(centres[a]), sb = plane_.side(centres[b]);
      if ((sa <= 0) == (sb <= 0)) continue;
      const Vec3 x = crossing(centres[a], centres[b], sa, sb);
      std::vector<int> facet;
      for (int v : cells[a]) {
        if (std::find(cells[b].begin(), cells[b].end(), v) != cells[b].end()) facet.push_back(v);
      }
      for (std::size_t i = 0; i < facet.size(); ++i) {
        for (std::size_t j = i + 1; j < facet.size(); ++j)
          crossings[std::minmax(facet[i], facet[j])].push_back(x);
      }
    }
    Layer& layer = add("voronoi-section", "Voronoi faces on the plane", Primitive::lines,
                       palette::voronoi_edge, 1.5f);
    const float far = 0.05f * plane_.extent;  // as the cut-away: what stays near the samples
    const auto near = [&](const Vec3& p) {
      for (int c = 0; c < 3; ++c) {
        if (p[c] < scene_.lower[c] - far || p[c] > scene_.upper[c] + far) return false;
      }
      return true;
    };
    for (const auto& [edge, points] : crossings) {
      if (points.size() != 2 || !near(points[0]) || !near(points[1])) continue;
      layer.positions.push_back(lifted(points[0]));
      layer.positions.push_back(lifted(points[1]));
    }
  }

  void surface() {
    const auto& points = r_.surface_points();
    Layer& layer =
        add("surface-section", "the surface on the plane", Primitive::lines, palette::curve, 3.0f);
    std::vector<Vec3> segments;
    for (const auto& t : r_.surface)
      cut_triangle({vec(points[t[0]]), vec(points[t[1]]), vec(points[t[2]])}, plane_, segments);
    for (const auto& p : segments) layer.positions.push_back(lifted(p));
  }

  // The poles near the plane (their centres within the band), by their labels at the stage's
  // end when it has them: inner red, outer orange.
  void poles_near_the_plane() {
    const auto& poles = r_.poles.poles;
    if (poles.empty() || request_.stage == Stage::samples || request_.stage == Stage::delaunay ||
        request_.stage == Stage::hull || request_.stage == Stage::surface)
      return;
    // Before the labelling, a pole is a pole: the stage knows no side yet.
    const std::vector<Label> labels =
        request_.stage < Stage::propagation ? std::vector<Label>{} : labels_at_this_stage();
    Layer& inner =
        add(labels.empty() ? "poles" : "inner-poles", labels.empty() ? "poles" : "inner poles",
            Primitive::points, palette::pole, 6);
    Layer& outer = add("outer-poles", "outer poles", Primitive::points, palette::outer_pole_3d, 6);
    Layer& unlabelled =
        add("unlabelled-poles", "unlabelled poles", Primitive::points, palette::unlabelled_pole, 6);
    for (std::size_t p = 0; p < poles.size(); ++p) {
      const Vec3 c = vec(poles[p].center);
      if (std::abs(plane_.side(c)) > band_) continue;
      const Label label = labels.empty() ? Label::inner : labels[p];
      Layer& layer = label == Label::outer ? outer : label == Label::inner ? inner : unlabelled;
      layer.positions.push_back(on_plane(c));
    }
  }

  // The labels the poles have at the stage shown, as the scene builder gives them: during the
  // labelling replay, those given so far; else the final ones. Empty for a method that labels
  // none.
  std::vector<Label> labels_at_this_stage() const { return labels_at_stage(r_, request_); }

  // The polar balls the plane cuts, as the circles of the cut (the paper's polar circles, in
  // any plane): inner and outer apart by the labels the stage knows, every ball_every-th pole,
  // at most ball_limit of each kind.
  void polar_circles() {
    const auto& poles = r_.poles.poles;
    const std::vector<Label> labels = labels_at_this_stage();
    std::vector<int> of_kind[3];
    const int every = std::max(1, request_.ball_every);
    // As in the scene builder: no ball larger than half the box's diagonal (outer poles far out).
    const float largest = 0.5f * distance(scene_.lower, scene_.upper);
    for (std::size_t p = 0; p < poles.size(); ++p) {
      if (poles[p].convex || p % every != 0 || float(poles[p].radius) > largest) continue;
      if (std::abs(plane_.side(vec(poles[p].center))) >= float(poles[p].radius)) continue;
      of_kind[labels.empty() ? 0 : int(labels[p])].push_back(int(p));
    }
    // Two directions across the plane.
    const Vec3& n = plane_.normal;
    Vec3 u = std::abs(n[0]) < 0.9f ? Vec3{0, -n[2], n[1]} : Vec3{-n[2], 0, n[0]};
    const float length = std::hypot(u[0], u[1], u[2]);
    for (auto& c : u) c /= length;
    const Vec3 v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    const char* ids[3] = {"polar-balls", "inner-balls", "outer-balls"};
    const char* names[3] = {
        labels.empty() ? "polar balls, cut" : "polar balls not yet labelled, cut",
        request_.stage < Stage::propagation ? "inner polar balls (as labelled later), cut"
                                            : "inner polar balls, cut",
        request_.stage < Stage::propagation ? "outer polar balls (as labelled later), cut"
                                            : "outer polar balls, cut"};
    const Color colours[3] = {palette::polar_ball_3d, palette::inner_ball, palette::outer_ball};
    for (int k = 0; k < 3; ++k) {
      const std::vector<int>& kind = of_kind[k];
      const std::size_t limit = request_.ball_limit > 0 ? std::size_t(request_.ball_limit) : 0;
      const std::size_t count = limit > 0 ? std::min(limit, kind.size()) : kind.size();
      Layer& layer = add(ids[k], names[k], Primitive::lines, colours[k], 1.5f);
      for (std::size_t i = 0; i < count; ++i) {
        const auto& pole = poles[kind[i * kind.size() / count]];
        const Vec3 centre = on_plane(vec(pole.center));
        const float side = plane_.side(vec(pole.center));
        const float radius = std::sqrt(float(pole.radius * pole.radius) - side * side);
        constexpr int sides = 48;
        const auto at = [&](int j) {
          const float angle = 2 * float(M_PI) * float(j) / sides;
          const float a = radius * std::cos(angle), b = radius * std::sin(angle);
          return Vec3{centre[0] + a * u[0] + b * v[0], centre[1] + a * u[1] + b * v[1],
                      centre[2] + a * u[2] + b * v[2]};
        };
        for (int j = 0; j < sides; ++j) {
          layer.positions.push_back(at(j));
          layer.positions.push_back(at(j + 1));
        }
      }
    }
  }

  void samples_near_the_plane() {
    Layer& layer = add("samples", "samples near the plane", Primitive::points, palette::sample, 6);
    for (int s = 0; s < n_; ++s) {
      const Vec3 p = vec(r_.sites[s]);
      if (std::abs(plane_.side(p)) <= band_) layer.positions.push_back(on_plane(p));
    }
  }

  const Reconstruction<3>& r_;
  const Request& request_;
  const int n_;
  Scene scene_;
  std::deque<Layer> layers_;  // a deque: references to layers stay valid as more are added
  Clip_plane plane_;
  float lift_ = 0, band_ = 0;
  std::function<Point<3>(int)> position_ = [this](int i) { return r_.sites[i]; };
};

}  // namespace

Scene build_section(const Reconstruction<3>& reconstruction, const Request& request) {
  return Section_builder(reconstruction, request).build();
}

}  // namespace sculpt::scene
