// SPDX-License-Identifier: GPL-3.0-or-later
// Manifold extraction (Amenta, Choi, Dey & Leekha 2000, section 4; the crust's "trimming",
// Amenta, Bern & Kamvysselis 1998): the methods that choose Delaunay triangles by a local rule
// (the crust, the co-cone) get a set that is a manifold only where the samples are dense and
// smooth; a few extra triangles stand inside or hang off it. Two steps make a surface of it:
//   prune: an edge is sharp when all its triangles lie within a wedge narrower than 90 degrees
//          (consecutive about it, they leave a gap wider than 3π/2: for two triangles, a fold
//          sharper than 90 degrees), or when it has one triangle; a triangle
//          on a sharp edge cannot be on a smooth closed surface, so it goes, and its neighbours
//          are looked at again. This is exact where the candidates are a closed surface with a
//          few extra triangles, but a single hole in them (undersampling) lets it eat the whole
//          surface, ring by ring from the hole's rim. So when it leaves a sample with no
//          triangle, the pruning is run again keeping the rims: a triangle with an edge of its
//          own goes only if it hangs free (held nowhere by a sheet, only where three or more
//          triangles meet); the hole stays and shows in the verdict;
//   walk:  from a triangle on the outside, go across each edge to the first triangle met when
//          turning about that edge from the outside, oriented the same way: this walks the outer
//          boundary of the triangles' union, which leaves out the triangles inside it that hang
//          on it. A piece not joined to it (the wall of a cavity, a second object) is walked from
//          its own extreme sample, facing out of the solid: into the cavity when it lies inside
//          the surface walked so far.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/stage_clock.hpp"
#include "edge_map.hpp"
#include "ray_crossings.hpp"
#include "vector3.hpp"

namespace sculpt {

namespace extraction_detail {

// The angle, in [0, 2π), at which the half-plane of a triangle with edge (a, b) and third
// vertex `apex` stands about that edge, measured from `start` (a unit vector perpendicular to the
// edge) towards `towards` (the unit vector perpendicular to both).
inline double angle_about_edge(const std::vector<Point<3>>& points, int a, const Vector& axis,
                               const Vector& start, const Vector& towards, int apex) {
  const Vector to_apex = minus(points[apex], points[a]);
  const double along = dot(to_apex, axis);
  const Vector across = {to_apex[0] - along * axis[0], to_apex[1] - along * axis[1],
                         to_apex[2] - along * axis[2]};
  const double angle = std::atan2(dot(across, towards), dot(across, start));
  return angle < 0 ? angle + 2 * M_PI : angle;
}

// A frame about the edge (a, b) of a triangle with third vertex c: the axis along the edge, the
// direction towards c and the triangle's normal for the order (a, b, c).
struct Edge_frame {
  Vector axis, start, normal;
  bool degenerate = false;
};

inline Edge_frame frame_of(const std::vector<Point<3>>& points, int a, int b, int c) {
  Edge_frame frame;
  Vector axis = minus(points[b], points[a]);
  const double length = std::sqrt(dot(axis, axis));
  Vector normal = cross(axis, minus(points[c], points[a]));
  const double area = std::sqrt(dot(normal, normal));
  if (length == 0 || area == 0) {
    frame.degenerate = true;
    return frame;
  }
  for (int k = 0; k < 3; ++k) {
    axis[k] /= length;
    normal[k] /= area;
  }
  frame.axis = axis;
  frame.normal = normal;
  frame.start = cross(normal, axis);  // in the triangle's plane, towards c
  return frame;
}

inline int third_vertex(const Facet<3>& t, int a, int b) {
  for (int v : t) {
    if (v != a && v != b) return v;
  }
  return -1;
}

}  // namespace extraction_detail

// How the pruning treats a triangle with an edge of its own.
enum class Rims { pruned, kept };

// Removes, repeatedly, the triangles on a sharp edge; returns the removed ones in order and
// leaves the others in `triangles`. `clock`, if given, is told how far it is.
inline std::vector<Facet<3>> prune_sharp_edges(const std::vector<Point<3>>& points,
                                               std::vector<Facet<3>>& triangles, Rims rims,
                                               const Stage_clock* clock = nullptr) {
  using namespace extraction_detail;
  const Edge_map edges(triangles);
  std::vector<char> removed(triangles.size(), 0);
  std::vector<Facet<3>> pruned;

  // (Into buffers reused from one question to the next: the pruning asks millions.)
  std::vector<int> around;
  std::vector<double> angles;
  const auto triangles_left_on = [&](int a, int b) -> const std::vector<int>& {
    around.clear();
    for (int t : edges.on(a, b)) {
      if (!removed[t]) around.push_back(t);
    }
    return around;
  };
  // Whether the triangles on edge (a, b) all lie within a wedge narrower than 90 degrees.
  const auto sharp_fold = [&](int a, int b, const std::vector<int>& on_edge) {
    if (on_edge.size() < 2) return false;
    const Edge_frame frame = frame_of(points, a, b, third_vertex(triangles[on_edge[0]], a, b));
    if (frame.degenerate) return false;
    angles.clear();
    for (int t : on_edge) {
      angles.push_back(angle_about_edge(points, a, frame.axis, frame.start, frame.normal,
                                        third_vertex(triangles[t], a, b)));
    }
    std::sort(angles.begin(), angles.end());
    double widest_gap = 2 * M_PI - (angles.back() - angles.front());
    for (std::size_t i = 1; i < angles.size(); ++i) {
      widest_gap = std::max(widest_gap, angles[i] - angles[i - 1]);
    }
    return widest_gap > 1.5 * M_PI;
  };
  // Whether a triangle must go: it stands on a sharp fold, or it has an edge of its own (no
  // other triangle) and, when rims are kept, is held by no edge shared with exactly one other
  // triangle (a sheet) but only where three or more triangles meet, or nowhere.
  const auto must_go = [&](int t) {
    const Facet<3>& triangle = triangles[t];
    bool free_edge = false, held_by_sheet = false;
    for (int j = 0; j < 3; ++j) {
      const int a = triangle[j], b = triangle[(j + 1) % 3];
      const auto& left = triangles_left_on(a, b);
      if (sharp_fold(a, b, left)) return true;
      free_edge = free_edge || left.size() == 1;
      held_by_sheet = held_by_sheet || left.size() == 2;
    }
    return free_edge && (rims == Rims::pruned || !held_by_sheet);
  };

  std::deque<int> to_check(triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) to_check[t] = t;
  std::size_t checked = 0;  // every triangle at least once, some again
  while (!to_check.empty()) {
    if (clock) clock->report_every(++checked, triangles.size(), 16384);
    const int t = to_check.front();
    to_check.pop_front();
    if (removed[t]) continue;
    const Facet<3>& triangle = triangles[t];
    if (!must_go(t)) continue;
    removed[t] = 1;
    pruned.push_back(triangle);
    for (int j = 0; j < 3; ++j) {
      for (int neighbour : edges.on(triangle[j], triangle[(j + 1) % 3])) {
        if (!removed[neighbour]) to_check.push_back(neighbour);
      }
    }
  }
  std::vector<Facet<3>> kept;
  kept.reserve(triangles.size() - pruned.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!removed[t]) kept.push_back(triangles[t]);
  }
  triangles = std::move(kept);
  return pruned;
}

// The pruning above, with rims pruned unless that leaves a sample that had triangles without any
// (or with rims kept at once, for a surface known to have borders). `rims` tells which ran.
inline std::vector<Facet<3>> prune_candidates(const std::vector<Point<3>>& points,
                                              std::vector<Facet<3>>& triangles, Rims& rims,
                                              const Stage_clock* clock = nullptr) {
  if (rims == Rims::kept) return prune_sharp_edges(points, triangles, Rims::kept, clock);
  const auto covered = [&](const std::vector<Facet<3>>& set) {
    std::vector<char> on(points.size(), 0);
    for (const auto& t : set) {
      for (int v : t) on[v] = 1;
    }
    return std::count(on.begin(), on.end(), 1);
  };
  std::vector<Facet<3>> kept = triangles;
  auto pruned = prune_sharp_edges(points, kept, Rims::pruned, clock);
  rims = Rims::pruned;
  if (covered(kept) < covered(triangles)) {
    rims = Rims::kept;
    kept = triangles;
    pruned = prune_sharp_edges(points, kept, Rims::kept, clock);
  }
  triangles = std::move(kept);
  return pruned;
}

// The outer boundary of the triangles' union, oriented outward: one walk per piece, each started
// at the triangle of the piece's extreme sample (largest x) whose normal points most along x.
// `clock`, if given, is told how far it is.
inline std::vector<Facet<3>> walk_outer_boundary(const std::vector<Point<3>>& points,
                                                 const std::vector<Facet<3>>& triangles,
                                                 const Stage_clock* clock = nullptr) {
  using namespace extraction_detail;
  const Edge_map edges(triangles);
  std::vector<char> taken(triangles.size(), 0);
  std::vector<char> on_surface(points.size(), 0);
  std::vector<Facet<3>> surface;

  // The directed edges of the triangles taken, a bit per direction of each edge (every triangle
  // taken or tried is one of `triangles`, so its edges are numbered). An edge used once in each
  // direction has its two triangles: no third can join it without using one direction twice.
  std::vector<std::uint8_t> used(edges.edge_count(), 0);
  const auto direction = [](int from, int to) { return from < to ? 1 : 2; };
  const auto take = [&](const Facet<3>& t) {
    surface.push_back(t);
    if (clock) clock->report_every(surface.size(), triangles.size(), 16384);
    for (int k = 0; k < 3; ++k) {
      used[edges.index(t[k], t[(k + 1) % 3])] |= direction(t[k], t[(k + 1) % 3]);
    }
  };

  // The pieces walked so far, with their bounding boxes: a piece can hold a sample inside only
  // if the inside test's ray from it passes through its box.
  struct Piece {
    std::size_t first, last;  // its triangles in `surface`
    Point<3> lower, upper;
    std::unique_ptr<Ray_crossings> crossings;       // made when first asked
    bool holds_ray_from(const Point<3>& p) const {  // the ray meets the box (slab test)
      double enter = 0, leave = HUGE_VAL;
      for (int k = 0; k < 3; ++k) {
        const double a = (lower[k] - p[k]) / ray_direction[k],
                     b = (upper[k] - p[k]) / ray_direction[k];
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
      }
      return enter <= leave;
    }
  };
  std::vector<Piece> pieces;

  std::vector<std::vector<int>> triangles_at(points.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int v : triangles[t]) triangles_at[v].push_back(t);
  }
  std::vector<int> by_x;
  for (int v = 0; v < static_cast<int>(points.size()); ++v) {
    if (!triangles_at[v].empty()) by_x.push_back(v);
  }
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return points[a][0] > points[b][0]; });

  // Whether a triangle can join the surface taken so far: no directed edge used twice, hence
  // no third triangle on an edge. Where the candidates have a hole, the walk could otherwise
  // slip through it to triangles inside and come back to the outer ones from behind.
  const auto fits = [&](const Facet<3>& t) {
    for (int k = 0; k < 3; ++k) {
      if (used[edges.index(t[k], t[(k + 1) % 3])] & direction(t[k], t[(k + 1) % 3])) return false;
    }
    return true;
  };

  for (int start : by_x) {
    if (on_surface[start]) continue;
    // The seed: at a piece's extreme sample the outside of that piece lies towards +x; the
    // solid's outside too, unless the piece lies inside the surface walked so far (a cavity).
    bool inside = false;
    for (Piece& piece : pieces) {
      if (!piece.holds_ray_from(points[start])) continue;
      if (!piece.crossings) {
        piece.crossings = std::make_unique<Ray_crossings>(points, surface, piece.first, piece.last);
      }
      inside ^= piece.crossings->odd_from(points[start]);
    }
    int seed = -1;
    double best = -1;
    Facet<3> oriented{};
    for (int t : triangles_at[start]) {
      if (taken[t]) continue;
      const auto& [a, b, c] = triangles[t];
      const Vector normal = normal_of(points, a, b, c);
      const double length = std::sqrt(dot(normal, normal));
      if (length == 0) continue;
      const double along_x = std::abs(normal[0]) / length;
      const Facet<3> facing = (normal[0] >= 0) != inside ? Facet<3>{a, b, c} : Facet<3>{a, c, b};
      if (along_x > best && fits(facing)) {
        best = along_x;
        seed = t;
        oriented = facing;
      }
    }
    if (seed < 0) continue;
    const std::size_t first_of_piece = surface.size();
    std::deque<Facet<3>> front{oriented};
    taken[seed] = 1;
    take(oriented);
    while (!front.empty()) {
      const Facet<3> current = front.front();
      front.pop_front();
      for (int j = 0; j < 3; ++j) {
        const int a = current[j], b = current[(j + 1) % 3], c = current[(j + 2) % 3];
        const Edge_frame frame = frame_of(points, a, b, c);
        if (frame.degenerate) continue;
        // Turn about (a, b) from the current triangle towards its outside: the first triangle
        // met is the next piece of the outer boundary.
        int next = -1;
        double nearest = 2 * M_PI;
        for (int t : edges.on(a, b)) {
          const int apex = third_vertex(triangles[t], a, b);
          if (apex == c) continue;
          const double angle =
              angle_about_edge(points, a, frame.axis, frame.start, frame.normal, apex);
          if (angle > 0 && angle < nearest) {
            nearest = angle;
            next = t;
          }
        }
        if (next < 0 || taken[next]) continue;
        const Facet<3> next_oriented{b, a, third_vertex(triangles[next], a, b)};
        if (!fits(next_oriented)) continue;
        taken[next] = 1;
        take(next_oriented);
        front.push_back(next_oriented);
      }
    }
    Piece piece{first_of_piece, surface.size(), points[start], points[start], nullptr};
    for (std::size_t t = first_of_piece; t < surface.size(); ++t) {
      for (int v : surface[t]) {
        on_surface[v] = 1;
        for (int k = 0; k < 3; ++k) {
          piece.lower[k] = std::min(piece.lower[k], points[v][k]);
          piece.upper[k] = std::max(piece.upper[k], points[v][k]);
        }
      }
    }
    pieces.push_back(std::move(piece));
  }
  return surface;
}

// The extraction as a method's last stages: prune the chosen candidates, then walk; the
// candidates stage and the statistics record both.
inline void extract_manifold(const std::vector<Point<3>>& samples, Reconstruction<3>& result,
                             Stage_clock& clock, Rims rims = Rims::pruned) {
  // In a canonical order: CGAL's facet iterator reports a facet from whichever of its two cells
  // has the lower address, so the order the methods find them in (and their orientation) changes
  // from run to run, and the pruning and the walk depend on it where the samples are degenerate
  // (CGAL's femur: a few holes more or less from one run to the next in one process).
  auto& chosen = result.candidates.chosen;
  for (auto& t : chosen) std::sort(t.begin(), t.end());
  std::sort(chosen.begin(), chosen.end());
  result.stats.candidate_facets = chosen.size();
  clock.start("pruning");
  std::vector<Facet<3>> kept = chosen;
  result.candidates.pruned = prune_candidates(samples, kept, rims, &clock);
  result.candidates.rims_kept = result.stats.rims_kept = rims == Rims::kept;
  result.stats.pruned_facets = result.candidates.pruned.size();
  clock.start("walk");
  result.surface = walk_outer_boundary(samples, kept, &clock);
}

}  // namespace sculpt
