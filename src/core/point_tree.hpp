// A k-d tree of points answering one question: is there a point strictly closer to x than r
// that a test accepts? The circumball queries (circumball_query.hpp) ask it of the poles for
// every all-sample cell: x its circumcentre, r its circumradius plus a margin, the test CGAL's
// exact in-sphere predicate. The search stops at the first point accepted, and skips a node
// whose bounding box lies at distance r or more. Points are stored in the tree's order, so a
// leaf's points are contiguous in memory.
#pragma once

#include <algorithm>
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
  std::vector<Node> nodes_;
};

}  // namespace sculpt
