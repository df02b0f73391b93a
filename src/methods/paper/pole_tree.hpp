// SPDX-License-Identifier: GPL-3.0-or-later
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
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

template <int D>
class Pole_tree {
 public:
  // The centres are copied in the tree's order, each travelling with its pole while the medians
  // are found: a leaf's centres lie together, where reading them through the poles' numbers
  // jumped about memory (bunny00 subdivided, paper: the separation's searches 0.13 -> 0.09 s).
  explicit Pole_tree(const std::vector<Pole<D>>& poles) {
    entries_.resize(poles.size());
    for (std::size_t i = 0; i < poles.size(); ++i) {
      entries_[i] = {poles[i].center, static_cast<int>(i)};
    }
    leaf_of_.assign(poles.size(), -1);
    if (!poles.empty()) build(0, static_cast<int>(poles.size()), -1);
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

  struct Entry {
    Point<D> center;
    int pole;
  };

  struct Node {
    Point<D> box_lo, box_hi;  // tight bounding box of the node's poles
    int begin, end;           // range in entries_
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
    node.box_lo = node.box_hi = entries_[begin].center;
    for (int i = begin; i < end; ++i) {
      for (int k = 0; k < D; ++k) {
        node.box_lo[k] = std::min(node.box_lo[k], entries_[i].center[k]);
        node.box_hi[k] = std::max(node.box_hi[k], entries_[i].center[k]);
      }
    }
    if (end - begin <= leaf_size) {
      for (int i = begin; i < end; ++i) leaf_of_[entries_[i].pole] = id;
    } else {
      int axis = 0;  // split the widest side at the median
      for (int k = 1; k < D; ++k) {
        if (node.box_hi[k] - node.box_lo[k] > node.box_hi[axis] - node.box_lo[axis]) axis = k;
      }
      const int middle = begin + (end - begin) / 2;
      std::nth_element(
          entries_.begin() + begin, entries_.begin() + middle, entries_.begin() + end,
          [&](const Entry& a, const Entry& b) { return a.center[axis] < b.center[axis]; });
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
        if (inside(entries_[i].center, lo, hi)) visit(entries_[i].pole);
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

  std::vector<Entry> entries_;  // in the tree's order; a node's are [begin, end)
  std::vector<int> leaf_of_;
  std::vector<Node> nodes_;
};

}  // namespace sculpt
