// SPDX-License-Identifier: GPL-3.0-or-later
// A k-d tree of points answering two questions. Is there a point strictly closer to x than r
// that a test accepts? The circumball queries (circumball_query.hpp) ask it of the poles for
// every all-sample cell: x its circumcentre, r its circumradius plus a margin, the test CGAL's
// exact in-sphere predicate. The search stops at the first point accepted, and skips a node
// whose bounding box lies at distance r or more. How far is each point from its k-th nearest?
// The test for facets spanning an opening (spanning_openings.hpp) asks it of the samples, for
// their spacing, or only whether there are k points within a distance. Points are stored in the
// tree's order, so a leaf's points are contiguous in memory, and neighbouring queries run one after
// the other.
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
    // Each point travels with its index while the medians are found: the comparisons read
    // contiguous memory rather than jumping through an index array.
    std::vector<Entry> entries;
    entries.reserve(count);
    for (int i = 0; i < count; ++i) entries.push_back({first[i], i});
    if (count > 0) build(entries, 0, count);
    input_index_.reserve(count);
    for (const Entry& entry : entries) input_index_.push_back(entry.index);
    std::vector<Entry>().swap(entries);  // freed before the points are copied
    points_.reserve(count);
    for (int i : input_index_) points_.push_back(first[i]);
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
      if (gap2(node, x) >= r2) continue;
      if (node.left >= 0) {
        stack[top++] = node.right;
        stack[top++] = node.left;
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) {
        if (distance2(x, points_[i]) < r2 && accept(points_[i])) return true;
      }
    }
    return false;
  }

  // The same, with accept(p, i) told the index i of p among the points given.
  template <class Accept>
  bool any_within_indexed(const Point<D>& x, double r2, Accept&& accept) const {
    return any_within(x, r2, [&](const Point<D>& p) {
      return accept(p, input_index_[static_cast<std::size_t>(&p - points_.data())]);
    });
  }

  bool any_within(const Point<D>& x, double r2) const {
    return any_within(x, r2, [](const Point<D>&) { return true; });
  }

  // The points' indices in the order given, listed in the tree's order: neighbours come one
  // after another, so queries about the points made in this order find the tree in cache.
  const std::vector<int>& tree_order() const { return input_index_; }

  // How many points lie at squared distance below r2 from x, counting up to `enough` (where the
  // search stops).
  int count_within(const Point<D>& x, double r2, int enough) const {
    int count = 0;
    any_within(x, r2, [&](const Point<D>&) { return ++count >= enough; });
    return count;
  }

  // The squared distance from x to its k-th nearest point (a point at x counts; 1 <= k <=
  // most_neighbours), or infinity when there are fewer than k points.
  double kth_nearest_distance2(const Point<D>& x, int k) const {
    assert(k >= 1 && k <= most_neighbours);
    Nearest nearest(k);
    if (!nodes_.empty()) search_nearest(x, nearest, -1);
    return nearest.bound();
  }

  // For every point, in the order given, the squared distance to its k-th nearest point (itself
  // the first; 1 <= k <= most_neighbours), or infinity when there are fewer than k points. A
  // point's own leaf is searched first: its neighbours are mostly there, so the bound they give
  // prunes the descent from the root, which then skips that leaf.
  static constexpr int most_neighbours = 15;
  std::vector<double> kth_nearest_distances2(int k) const {
    std::vector<double> result(points_.size());
    for_each_k_nearest(k, [&](int point, Nearest& nearest) { result[point] = nearest.bound(); });
    return result;
  }

  // The k nearest points to x (fewer when there are fewer), nearest first: their indices in the
  // order given.
  std::vector<int> k_nearest_to(const Point<D>& x, int k) const {
    assert(k >= 1 && k <= most_neighbours);
    Nearest nearest(k);
    if (!nodes_.empty()) search_nearest(x, nearest, -1);
    const auto* entry = nearest.sorted();
    std::vector<int> result(nearest.found());
    for (int j = 0; j < nearest.found(); ++j) result[j] = input_index_[entry[j].second];
    return result;
  }

  // For every point, in the order given, its k nearest points (itself among them, unless k or
  // more others coincide with it), nearest
  // first: their indices in the order given, k per point (-1 where there are fewer than k).
  std::vector<int> k_nearest(int k) const {
    std::vector<int> result(points_.size() * k, -1);
    for_each_k_nearest(k, [&](int point, Nearest& nearest) {
      const auto* entry = nearest.sorted();
      for (int j = 0; j < nearest.found(); ++j)
        result[std::size_t(point) * k + j] = input_index_[entry[j].second];
    });
    return result;
  }

 private:
  static constexpr int leaf_size = 8;

  struct Node {
    Point<D> lo, hi;
    int begin, end;
    int left = -1, right = -1;
  };

  static double distance2(const Point<D>& a, const Point<D>& b) {
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
    return d2;
  }

  // Calls use(point's index in the order given, its k nearest) for every point.
  template <class Use>
  void for_each_k_nearest(int k, Use&& use) const {
    assert(k >= 1 && k <= most_neighbours);
    for (int leaf = 0; leaf < static_cast<int>(nodes_.size()); ++leaf) {
      const Node& node = nodes_[leaf];
      if (node.left >= 0) continue;
      for (int i = node.begin; i < node.end; ++i) {
        Nearest nearest(k);
        for (int j = node.begin; j < node.end; ++j)
          nearest.offer(distance2(points_[i], points_[j]), j);
        search_nearest(points_[i], nearest, leaf);
        use(input_index_[i], nearest);
      }
    }
  }

  // The squared distance from x to the node's bounding box (0 inside it).
  static double gap2(const Node& node, const Point<D>& x) {
    double g2 = 0;
    for (int k = 0; k < D; ++k) {
      const double gap = std::max({node.lo[k] - x[k], 0.0, x[k] - node.hi[k]});
      g2 += gap * gap;
    }
    return g2;
  }

  // The k nearest points offered (squared distance, position in the tree's order), as a
  // max-heap (no allocation: k is small).
  class Nearest {
   public:
    using Entry = std::pair<double, int>;
    explicit Nearest(int k) : k_(k) {}
    double bound() const { return found_ < k_ ? INFINITY : heap_[0].first; }
    void offer(double d2, int position) {
      if (d2 >= bound()) return;
      heap_[found_++] = {d2, position};
      std::push_heap(heap_.begin(), heap_.begin() + found_);
      if (found_ > k_) std::pop_heap(heap_.begin(), heap_.begin() + found_--);
    }
    // Nearest first.
    const Entry* sorted() {
      std::sort_heap(heap_.begin(), heap_.begin() + found_);
      return heap_.data();
    }
    int found() const { return found_; }

   private:
    std::array<Entry, most_neighbours + 1> heap_;
    int k_;
    int found_ = 0;
  };

  // Offers the points of every leaf but `skip` that could be nearer to x than the bound: the
  // nearer child first, a node no nearer than the bound skipped.
  void search_nearest(const Point<D>& x, Nearest& nearest, int skip) const {
    struct Visit {
      int node;
      double gap2;
    };
    Visit stack[64];
    int top = 0;
    stack[top++] = {0, gap2(nodes_[0], x)};
    while (top > 0) {
      const Visit visit = stack[--top];
      if (visit.gap2 >= nearest.bound() || visit.node == skip) continue;
      const Node& node = nodes_[visit.node];
      if (node.left >= 0) {
        const Visit left{node.left, gap2(nodes_[node.left], x)};
        const Visit right{node.right, gap2(nodes_[node.right], x)};
        const bool left_first = left.gap2 <= right.gap2;
        stack[top++] = left_first ? right : left;
        stack[top++] = left_first ? left : right;
        continue;
      }
      for (int i = node.begin; i < node.end; ++i) nearest.offer(distance2(x, points_[i]), i);
    }
  }

  struct Entry {
    Point<D> point;
    int index;  // in the order given
  };

  // Depth is at most log2(n / leaf_size) + 1 < 64: medians halve every range.
  int build(std::vector<Entry>& entries, int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node node;
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = entries[begin].point;
    for (int i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        node.lo[k] = std::min(node.lo[k], entries[i].point[k]);
        node.hi[k] = std::max(node.hi[k], entries[i].point[k]);
      }
    }
    if (end - begin > leaf_size) {
      int axis = 0;  // split the widest side at the median
      for (int k = 1; k < D; ++k) {
        if (node.hi[k] - node.lo[k] > node.hi[axis] - node.lo[axis]) axis = k;
      }
      const int middle = begin + (end - begin) / 2;
      std::nth_element(
          entries.begin() + begin, entries.begin() + middle, entries.begin() + end,
          [axis](const Entry& a, const Entry& b) { return a.point[axis] < b.point[axis]; });
      node.left = build(entries, begin, middle);
      node.right = build(entries, middle, end);
    }
    nodes_[id] = node;
    return id;
  }

  std::vector<Point<D>> points_;  // in the tree's order
  std::vector<int> input_index_;  // of each of them
  std::vector<Node> nodes_;
};

}  // namespace sculpt
