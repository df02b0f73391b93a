// SPDX-License-Identifier: GPL-3.0-or-later
#include "thin_handles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_set>

#include "edge_keys.hpp"

namespace sculpt {
namespace {

double distance(const Point<3>& a, const Point<3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The surface as half-edges: each vertex's outgoing ones sorted by the vertex they lead to, with
// the triangle on their left. On a closed 2-manifold every edge is two half-edges, so a vertex's
// outgoing half-edges name each of its neighbours once.
class Half_edges {
 public:
  Half_edges(std::size_t point_count, const std::vector<Facet<3>>& triangles)
      : triangles_(triangles), offsets_(point_count + 1, 0) {
    for (const auto& t : triangles) {
      for (int v : t) ++offsets_[v + 1];
    }
    for (std::size_t v = 0; v < point_count; ++v) offsets_[v + 1] += offsets_[v];
    entries_.resize(offsets_.back());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      for (int j = 0; j < 3; ++j) {
        entries_[fill[triangles[f][j]]++] = {triangles[f][(j + 1) % 3], static_cast<int>(f)};
      }
    }
    for (std::size_t v = 0; v < point_count; ++v) {
      const auto first = entries_.begin() + static_cast<std::ptrdiff_t>(offsets_[v]);
      const auto last = entries_.begin() + static_cast<std::ptrdiff_t>(offsets_[v + 1]);
      std::sort(first, last);
      // Two triangles that both go a -> b are not oriented alike across their edge.
      oriented_ = oriented_ && std::adjacent_find(first, last, [](const Entry& x, const Entry& y) {
                                 return x.to == y.to;
                               }) == last;
    }
  }

  // Whether every edge is two opposite half-edges: the triangles are oriented consistently.
  bool oriented() const { return oriented_; }

  struct Entry {
    int to;
    int triangle;
    bool operator<(const Entry& other) const { return to < other.to; }
  };

  const Entry* begin(int v) const { return entries_.data() + offsets_[v]; }
  const Entry* end(int v) const { return entries_.data() + offsets_[v + 1]; }

  // The triangle on the left of a -> b, or -1 when a and b are not neighbours.
  int triangle(int a, int b) const {
    const Entry* found = std::lower_bound(begin(a), end(a), Entry{b, 0});
    return found != end(a) && found->to == b ? found->triangle : -1;
  }
  bool adjacent(int a, int b) const { return triangle(a, b) >= 0; }

  // The third vertex of the triangle on the left of a -> b.
  int apex(int a, int b) const {
    const int f = triangle(a, b);
    if (f < 0) return -1;
    const auto& t = triangles_[f];
    for (int v : t) {
      if (v != a && v != b) return v;
    }
    return -1;
  }

 private:
  const std::vector<Facet<3>>& triangles_;
  std::vector<std::size_t> offsets_;
  std::vector<Entry> entries_;
  bool oriented_ = true;
};

// The samples on the triangles in the order a breadth-first walk over the surface meets them,
// each component from its first sample.
std::vector<int> walk_order(std::size_t point_count, const std::vector<Facet<3>>& triangles) {
  const Half_edges half_edges(point_count, triangles);
  std::vector<int> order;
  std::vector<bool> met(point_count, false);
  for (int start = 0; start < static_cast<int>(point_count); ++start) {
    if (met[start] || half_edges.begin(start) == half_edges.end(start)) continue;
    met[start] = true;
    order.push_back(start);
    for (std::size_t head = order.size() - 1; head < order.size(); ++head) {
      for (const auto* e = half_edges.begin(order[head]); e != half_edges.end(order[head]); ++e) {
        if (!met[e->to]) {
          met[e->to] = true;
          order.push_back(e->to);
        }
      }
    }
  }
  return order;
}

class Thin_handle_search {
 public:
  Thin_handle_search(const std::vector<Point<3>>& points, const std::vector<Facet<3>>& triangles,
                     std::size_t genus)
      : points_(points),
        triangles_(triangles),
        genus_(genus),
        half_edges_(points.size(), triangles),
        seen_(triangles.size(), 0),
        used_(points.size(), false),
        nearest_(points.size(), 0),
        // Flooding is bounded: a loop around a small disc is rejected after a few triangles, a
        // separating neck costs the smaller side; a pathological surface stops the search early.
        budget_(64 * triangles.size() + 4096) {}

  std::vector<Thin_handle> run() {
    // The search walks half-edges: triangles oriented every which way are not searched.
    if (!half_edges_.oriented()) return {};
    const int n = static_cast<int>(points_.size());
    for (int v = 0; v < n; ++v) nearest_[v] = nearest_neighbour_distance(v);
    // Triangles first (the thinnest necks), then quadrilaterals; each cycle is met once, from
    // its smallest sample u. Common neighbours are found by merging two sorted lists, which
    // are contiguous in memory.
    for (int u = 0; u < n && !done(); ++u) {
      for (const auto* v = half_edges_.begin(u); v != half_edges_.end(u) && !done(); ++v) {
        if (v->to < u) continue;
        common_neighbours(u, v->to, [&](int w) {
          if (w <= v->to) return;
          if (w == half_edges_.apex(u, v->to) || w == half_edges_.apex(v->to, u)) return;
          consider({u, v->to, w, -1});  // not a triangle of the surface
        });
      }
    }
    for (int u = 0; u < n && !done(); ++u) {
      // u - v - x - w - u: v and w neighbours of u (v < w) that are not neighbours of each other,
      // x a common neighbour of theirs that is not u's.
      for (const auto* v = half_edges_.begin(u); v != half_edges_.end(u) && !done(); ++v) {
        if (v->to < u) continue;
        for (const auto* w = v + 1; w != half_edges_.end(u) && !done(); ++w) {
          if (half_edges_.adjacent(v->to, w->to)) continue;  // a chord v - w
          common_neighbours(v->to, w->to, [&](int x) {
            if (x <= u || half_edges_.adjacent(u, x)) return;  // u itself, or a chord u - x
            consider({u, v->to, x, w->to});
          });
        }
      }
    }
    return found_;
  }

 private:
  // Calls `visit` with each common neighbour of a and b, until the search is done.
  template <class Visit>
  void common_neighbours(int a, int b, Visit&& visit) {
    const auto *i = half_edges_.begin(a), *j = half_edges_.begin(b);
    while (i != half_edges_.end(a) && j != half_edges_.end(b) && !done()) {
      if (i->to < j->to) {
        ++i;
      } else if (j->to < i->to) {
        ++j;
      } else {
        visit(i->to);
        ++i;
        ++j;
      }
    }
  }

  bool done() const { return found_.size() >= genus_ || budget_ == 0; }

  static int length(const std::array<int, 4>& loop) { return loop[3] < 0 ? 3 : 4; }

  void consider(const std::array<int, 4>& loop) {
    const int k = length(loop);
    for (int i = 0; i < k; ++i) {
      if (used_[loop[i]]) return;
    }
    const double ratio = width_over_spacing(loop);
    if (!(ratio <= thin_neck) || is_link_of_a_sample(loop)) return;
    Loop_edges edges{};
    for (int i = 0; i < k; ++i) edges[i] = edge_key(loop[i], loop[(i + 1) % k]);
    if (!sides_meet(loop, edges)) return;
    for (int i = 0; i < k; ++i) used_[loop[i]] = true;
    cut_.insert(edges.begin(), edges.begin() + k);
    found_.push_back({loop, ratio});
  }

  // The commonest short loop bounds the triangles around one sample of three or four: it is
  // known so at once, without a flood.
  bool is_link_of_a_sample(const std::array<int, 4>& loop) const {
    const int k = length(loop);
    for (const int apex :
         {half_edges_.apex(loop[0], loop[1]), half_edges_.apex(loop[1], loop[0])}) {
      if (half_edges_.end(apex) - half_edges_.begin(apex) != k) continue;
      bool all = true;
      for (int i = 0; i < k; ++i) all = all && half_edges_.adjacent(apex, loop[i]);
      if (all) return true;
    }
    return false;
  }

  double nearest_neighbour_distance(int v) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto* e = half_edges_.begin(v); e != half_edges_.end(v); ++e) {
      nearest = std::min(nearest, distance(points_[v], points_[e->to]));
    }
    return nearest;
  }

  // The loop's longest edge over the samples' spacing there: the mean, over its samples, of the
  // distance to their nearest neighbour on the surface.
  double width_over_spacing(const std::array<int, 4>& loop) const {
    const int k = length(loop);
    double longest = 0, spacing = 0;
    for (int i = 0; i < k; ++i) {
      longest = std::max(longest, distance(points_[loop[i]], points_[loop[(i + 1) % k]]));
      spacing += nearest_[loop[i]] / k;
    }
    return spacing > 0 ? longest / spacing : 0;
  }

  using Loop_edges = std::array<std::uint64_t, 4>;  // unused ones 0: no edge (a vertex to itself)

  bool crosses(int a, int b, const Loop_edges& loop_edges) const {
    const auto key = edge_key(a, b);
    return std::find(loop_edges.begin(), loop_edges.end(), key) != loop_edges.end() ||
           (!cut_.empty() && cut_.count(key) > 0);
  }

  // Whether the triangles on the two sides of the loop's first edge are joined on the surface
  // cut along the loop and the loops kept: the loop is then independent of them. Both sides are
  // flooded a triangle at a time in turn; the first to run out of triangles is a piece the loop
  // cuts off.
  bool sides_meet(const std::array<int, 4>& loop, const Loop_edges& loop_edges) {
    ++round_;
    const std::uint32_t mark[2] = {2 * round_, 2 * round_ + 1};
    // Breadth first: a queue of triangles (kept between calls) and where it is read.
    std::size_t head[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      front_[side].clear();
      const int start = half_edges_.triangle(loop[side], loop[1 - side]);
      if (start < 0) return false;
      front_[side].push_back(start);
      seen_[start] = mark[side];
    }
    auto& front = front_;
    for (;;) {
      for (int side = 0; side < 2; ++side) {
        if (head[side] == front[side].size()) return false;
        if (budget_ == 0) return false;
        --budget_;
        const int f = front[side][head[side]++];
        const auto& t = triangles_[f];
        for (int j = 0; j < 3; ++j) {
          const int a = t[j], b = t[(j + 1) % 3];
          if (crosses(a, b, loop_edges)) continue;
          const int next = half_edges_.triangle(b, a);
          if (next < 0) continue;
          if (seen_[next] == mark[1 - side]) return true;
          if (seen_[next] == mark[side]) continue;
          seen_[next] = mark[side];
          front[side].push_back(next);
        }
      }
    }
  }

  const std::vector<Point<3>>& points_;
  const std::vector<Facet<3>>& triangles_;
  const std::size_t genus_;
  const Half_edges half_edges_;
  std::vector<std::uint32_t> seen_;
  std::vector<bool> used_;
  std::vector<int> front_[2];
  std::vector<double> nearest_;  // each sample's distance to its nearest neighbour on the surface
  std::unordered_set<std::uint64_t> cut_;
  std::vector<Thin_handle> found_;
  std::uint32_t round_ = 0;
  std::size_t budget_;
};

}  // namespace

std::vector<Thin_handle> find_thin_handles(const std::vector<Point<3>>& points,
                                           const std::vector<Facet<3>>& triangles,
                                           std::size_t genus) {
  if (genus == 0 || triangles.empty()) return {};
  // The search reads the neighbours of neighbours: with the samples numbered as a breadth-first
  // walk over the surface meets them, those lie close in memory whatever order the samples came
  // in (a random torus of 1M samples: the whole search 1.0 s instead of 2.2).
  const auto order = walk_order(points.size(), triangles);
  std::vector<int> number(points.size(), -1);
  std::vector<Point<3>> walked_points(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    number[order[i]] = static_cast<int>(i);
    walked_points[i] = points[order[i]];
  }
  std::vector<Facet<3>> walked_triangles(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    for (int j = 0; j < 3; ++j) walked_triangles[f][j] = number[triangles[f][j]];
  }
  auto handles = Thin_handle_search(walked_points, walked_triangles, genus).run();
  for (auto& handle : handles) {
    for (int& v : handle.loop) {
      if (v >= 0) v = order[v];
    }
  }
  return handles;
}

void find_thin_handles_of(Reconstruction<3>& result) {
  auto& s = result.stats;
  result.thin_handles.clear();
  s.thin_handles = 0;
  const bool closed_manifold = s.facets > 0 && s.boundary_ridges == 0 &&
                               s.non_manifold_ridges == 0 && s.non_manifold_vertices == 0;
  const long genus = (2 * static_cast<long>(s.components) - s.euler_characteristic) / 2;
  if (!closed_manifold || genus <= 0) return;
  result.thin_handles =
      find_thin_handles(result.surface_points(), result.surface, static_cast<std::size_t>(genus));
  s.thin_handles = result.thin_handles.size();
}

}  // namespace sculpt
