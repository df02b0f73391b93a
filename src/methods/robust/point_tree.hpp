// A k-d tree of points answering one question: is any point strictly closer to x than r? The
// robust method asks it of the outer poles for every all-sample cell (x its circumcentre, r its
// circumradius): a cell whose circumball holds an outer pole would be destroyed by inserting the
// outer poles, as the paper's sculpting does (section 3.2). The search stops at the first point
// found, and a node is skipped when its bounding box lies at distance r or more.
#pragma once

#include <algorithm>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

template <int D>
class Point_tree {
 public:
  explicit Point_tree(std::vector<Point<D>> points) : points_(std::move(points)) {
    order_.resize(points_.size());
    std::iota(order_.begin(), order_.end(), 0);
    if (!points_.empty()) build(0, static_cast<int>(points_.size()));
  }

  // Whether a point lies at squared distance below r2 from x.
  bool any_within(const Point<D>& x, double r2) const {
    return !nodes_.empty() && search(0, x, r2);
  }

 private:
  static constexpr int leaf_size = 8;

  struct Node {
    Point<D> lo, hi;
    int begin, end;
    int left = -1, right = -1;
  };

  int build(int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node node;
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = points_[order_[begin]];
    for (int i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        node.lo[k] = std::min(node.lo[k], points_[order_[i]][k]);
        node.hi[k] = std::max(node.hi[k], points_[order_[i]][k]);
      }
    }
    if (end - begin > leaf_size) {
      int axis = 0;  // split the widest side at the median
      for (int k = 1; k < D; ++k) {
        if (node.hi[k] - node.lo[k] > node.hi[axis] - node.lo[axis]) axis = k;
      }
      const int middle = begin + (end - begin) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                       [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
      node.left = build(begin, middle);
      node.right = build(middle, end);
    }
    nodes_[id] = node;
    return id;
  }

  bool search(int id, const Point<D>& x, double r2) const {
    const Node& node = nodes_[id];
    double gap2 = 0;
    for (int k = 0; k < D; ++k) {
      const double gap = std::max({node.lo[k] - x[k], 0.0, x[k] - node.hi[k]});
      gap2 += gap * gap;
    }
    if (gap2 >= r2) return false;
    if (node.left >= 0) return search(node.left, x, r2) || search(node.right, x, r2);
    for (int i = node.begin; i < node.end; ++i) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = x[k] - points_[order_[i]][k];
        d2 += d * d;
      }
      if (d2 < r2) return true;
    }
    return false;
  }

  std::vector<Point<D>> points_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace sculpt
