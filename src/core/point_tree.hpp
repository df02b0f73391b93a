// A k-d tree of points answering two questions. Is there a point strictly closer to x than r
// that a test accepts? The circumball queries (circumball_query.hpp) ask it of the poles for
// every all-sample cell: x its circumcentre, r its circumradius plus a margin, the test CGAL's
// exact in-sphere predicate. The search stops at the first point accepted, and skips a node
// whose bounding box lies at distance r or more. How far is each point from its k-th nearest?
// The test for facets spanning an opening (spanning_openings.hpp) asks it of the samples, for
// their spacing. Points are stored in the tree's order, so a leaf's points are contiguous in
// memory, and neighbouring queries run one after the other.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

template <int D>
class Point_tree {
 public:
  // The points [first, last), which are copied.
  Point_tree(const Point<D>* first, const Point<D>* last) {
    const int count = static_cast<int>(last - first);
    std::vector<int> order(count);
    std::iota(order.begin(), order.end(), 0);
    if (count > 0) build(first, order, 0, count);
    points_.reserve(count);
    for (int i : order) points_.push_back(first[i]);
    input_index_ = std::move(order);
  }

  // Whether some point p at squared distance below r2 from x has accept(p) true.
  template <class Accept>
  bool any_within(const Point<D>& x, double r2, Accept&& accept) const {
    if (nodes_.empty()) return false;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      double gap2 = 0;
      for (int k = 0; k < D; ++k) {
        const double gap = std::max({node.lo[k] - x[k], 0.0, x[k] - node.hi[k]});
        gap2 += gap * gap;
      }
      if (gap2 >= r2) continue;
      if (node.left >= 0) {
        stack[top++] = node.right;
        stack[top++] = node.left;
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) {
        double d2 = 0;
        for (int k = 0; k < D; ++k) {
          const double d = x[k] - points_[i][k];
          d2 += d * d;
        }
        if (d2 < r2 && accept(points_[i])) return true;
      }
    }
    return false;
  }

  bool any_within(const Point<D>& x, double r2) const {
    return any_within(x, r2, [](const Point<D>&) { return true; });
  }

  // For every point, in the order given, the squared distance to its k-th nearest point (itself
  // the first).
  std::vector<double> kth_nearest_distances2(int k) const {
    std::vector<double> result(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      result[input_index_[i]] = kth_nearest_distance2(points_[i], k);
    }
    return result;
  }

  // The squared distance from x to its k-th nearest point (1 <= k <= most_neighbours; a point
  // at x itself counts), or infinity when there are fewer than k points. Nearer children are
  // searched first, and a node no nearer than the k-th distance found so far is skipped.
  static constexpr int most_neighbours = 15;
  double kth_nearest_distance2(const Point<D>& x, int k) const {
    // The k smallest squared distances so far, as a max-heap (no allocation: k is small).
    std::array<double, most_neighbours + 1> nearest;
    int found = 0;
    const auto bound = [&] { return found < k ? INFINITY : nearest[0]; };
    const auto gap2_to = [&](const Node& node) {
      double gap2 = 0;
      for (int d = 0; d < D; ++d) {
        const double gap = std::max({node.lo[d] - x[d], 0.0, x[d] - node.hi[d]});
        gap2 += gap * gap;
      }
      return gap2;
    };
    assert(k >= 1 && k <= most_neighbours);
    if (nodes_.empty()) return INFINITY;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (gap2_to(node) >= bound()) continue;
      if (node.left >= 0) {
        const bool left_first = gap2_to(nodes_[node.left]) <= gap2_to(nodes_[node.right]);
        stack[top++] = left_first ? node.right : node.left;
        stack[top++] = left_first ? node.left : node.right;
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) {
        double d2 = 0;
        for (int d = 0; d < D; ++d) {
          const double delta = x[d] - points_[i][d];
          d2 += delta * delta;
        }
        if (d2 >= bound()) continue;
        nearest[found++] = d2;
        std::push_heap(nearest.begin(), nearest.begin() + found);
        if (found > k) std::pop_heap(nearest.begin(), nearest.begin() + found--);
      }
    }
    return bound();
  }

 private:
  static constexpr int leaf_size = 8;

  struct Node {
    Point<D> lo, hi;
    int begin, end;
    int left = -1, right = -1;
  };

  // Depth is at most log2(n / leaf_size) + 1 < 64: medians halve every range.
  int build(const Point<D>* points, std::vector<int>& order, int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node node;
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = points[order[begin]];
    for (int i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        node.lo[k] = std::min(node.lo[k], points[order[i]][k]);
        node.hi[k] = std::max(node.hi[k], points[order[i]][k]);
      }
    }
    if (end - begin > leaf_size) {
      int axis = 0;  // split the widest side at the median
      for (int k = 1; k < D; ++k) {
        if (node.hi[k] - node.lo[k] > node.hi[axis] - node.lo[axis]) axis = k;
      }
      const int middle = begin + (end - begin) / 2;
      std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                       [&](int a, int b) { return points[a][axis] < points[b][axis]; });
      node.left = build(points, order, begin, middle);
      node.right = build(points, order, middle, end);
    }
    nodes_[id] = node;
    return id;
  }

  std::vector<Point<D>> points_;  // in the tree's order
  std::vector<int> input_index_;  // of each of them
  std::vector<Node> nodes_;
};

}  // namespace sculpt
