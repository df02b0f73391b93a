// A k-d tree over the poles that knows their labels, for the range searches of the pole
// separation (paper, section 3.1.1.2).
//
// Why not CGAL::Kd_tree: a labelled polar ball offers its label to every pole strictly inside
// its inscribed cube. Most of those poles already carry the same label (the polar balls of one
// side overlap heavily, and the convex seeds' balls are huge), so a plain range search reports
// O(n) poles per query and the separation becomes quadratic. Each node here counts its poles per
// label, and a query descends only into nodes holding a pole that is unlabelled or has the other
// label: every pole it reports is either newly labelled or a conflict.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

template <int D>
class Pole_tree {
 public:
  explicit Pole_tree(const std::vector<Point<D>>& centers) : centers_(centers) {
    order_.resize(centers.size());
    std::iota(order_.begin(), order_.end(), 0);
    leaf_of_.assign(centers.size(), -1);
    if (!centers.empty()) build(0, static_cast<int>(centers.size()), -1);
  }

  // Moves a pole from one label to another in the counts of its leaf and the leaf's ancestors.
  void relabel(int pole, Label from, Label to) {
    for (int node = leaf_of_[pole]; node >= 0; node = nodes_[node].parent) {
      --nodes_[node].count[index(from)];
      ++nodes_[node].count[index(to)];
    }
  }

  // Calls visit(pole) for every pole strictly inside the open box |x - center| < half_side (per
  // axis) whose label is not `label`.
  template <class Visit>
  void for_each_other_label_in_cube(const Point<D>& center, double half_side, Label label,
                                    Visit&& visit) const {
    if (nodes_.empty()) return;
    Point<D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = center[k] - half_side;
      hi[k] = center[k] + half_side;
    }
    const int wanted_a = label == Label::inner ? index(Label::outer) : index(Label::inner);
    const int wanted_b = index(Label::unlabelled);
    search(0, lo, hi, wanted_a, wanted_b, visit);
  }

 private:
  static constexpr int leaf_size = 8;

  struct Node {
    Point<D> box_lo, box_hi;  // tight bounding box of the node's poles
    int begin, end;           // range in order_
    int left = -1, right = -1, parent = -1;
    std::array<int, 3> count{};  // poles per label (unlabelled, inner, outer)
  };

  static int index(Label label) { return static_cast<int>(label); }

  int build(int begin, int end, int parent) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node node;
    node.begin = begin;
    node.end = end;
    node.parent = parent;
    node.count[index(Label::unlabelled)] = end - begin;
    node.box_lo = node.box_hi = centers_[order_[begin]];
    for (int i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        node.box_lo[k] = std::min(node.box_lo[k], centers_[order_[i]][k]);
        node.box_hi[k] = std::max(node.box_hi[k], centers_[order_[i]][k]);
      }
    }
    if (end - begin <= leaf_size) {
      for (int i = begin; i < end; ++i) leaf_of_[order_[i]] = id;
    } else {
      int axis = 0;  // split the widest side at the median
      for (int k = 1; k < D; ++k) {
        if (node.box_hi[k] - node.box_lo[k] > node.box_hi[axis] - node.box_lo[axis]) axis = k;
      }
      const int middle = begin + (end - begin) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                       [&](int a, int b) { return centers_[a][axis] < centers_[b][axis]; });
      node.left = build(begin, middle, id);
      node.right = build(middle, end, id);
    }
    nodes_[id] = node;
    return id;
  }

  template <class Visit>
  void search(int id, const Point<D>& lo, const Point<D>& hi, int wanted_a, int wanted_b,
              Visit& visit) const {
    const Node& node = nodes_[id];
    if (node.count[wanted_a] + node.count[wanted_b] == 0) return;
    for (int k = 0; k < D; ++k) {
      if (node.box_hi[k] <= lo[k] || node.box_lo[k] >= hi[k]) return;
    }
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) {
        const int pole = order_[i];
        if (inside(centers_[pole], lo, hi)) visit(pole);
      }
      return;
    }
    search(node.left, lo, hi, wanted_a, wanted_b, visit);
    search(node.right, lo, hi, wanted_a, wanted_b, visit);
  }

  static bool inside(const Point<D>& p, const Point<D>& lo, const Point<D>& hi) {
    for (int k = 0; k < D; ++k) {
      if (!(p[k] > lo[k] && p[k] < hi[k])) return false;
    }
    return true;
  }

  const std::vector<Point<D>>& centers_;
  std::vector<int> order_;
  std::vector<int> leaf_of_;
  std::vector<Node> nodes_;
};

}  // namespace sculpt
