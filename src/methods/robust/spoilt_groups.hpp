// SPDX-License-Identifier: GPL-3.0-or-later
// The robust carving's groups of outer cells spoilt by noise (solid_openings.hpp opens handles
// with them): a group whose removal at once fails at a few of its vertices only.
#pragma once

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "buried_samples.hpp"

namespace sculpt {

template <class Traits>
class Spoilt_groups : public Buried_samples<Traits> {
 public:
  using Buried_samples<Traits>::Buried_samples;

 protected:
  using Base = Buried_samples<Traits>;
  static constexpr int D = Traits::dimension;
  using Base::is_outside;
  using Base::manifold_at;
  using Base::outside_;
  using Base::set_outside;
  using Base::solid_cells_at_;
  using typename Base::Cell_handle;
  using typename Base::Vertex_handle;

  // A group whose removal fails at a few of its vertices only, where noise bends the surface
  // (at most spoilt_share of them: a torus's hole through samples noisy by a tenth of their
  // spacing fails at 1 to 4 of some 200), still shows a tunnel the poles see whole: `group` is
  // cut down to what can go. At each vertex that would leave the solid or stop being a
  // manifold, one cell of the group stays, until no vertex fails (at most 256 passes); only
  // cells still reaching the outside through the group are kept. (Keeping every cell beside the
  // solid at a failing vertex cascaded: a torus's hole of 545 cells, spoilt at one vertex, was
  // cut to 13 that opened two handles, and was refused.)
  // False when the group as a whole fails at more vertices (the share is the whole group's;
  // the passes that follow cut on until none fails), or nothing is left. The removal may then
  // open one handle at most (fewest_euler_change_of_a_spoilt_group): between limbs that touch, a
  // group spoilt at a few vertices opens several at once, through the touchings (CGAL's camel:
  // 3, homer: 2), where a hole opens one. A group cut down once is not cut down again in a
  // later round (spoilt_before_), whether its removal went or not: a region has one such chance.
  static constexpr double spoilt_share = 0.05;
  static constexpr int fewest_euler_change_of_a_spoilt_group = -1;  // one handle opened
  bool without_spoilt_vertices(std::vector<Cell_handle>& group) {
    if (spoilt_before_.size() != outside_.size()) spoilt_before_.assign(outside_.size(), 0);
    for (Cell_handle cell : group) {
      if (spoilt_before_[cell->info()]) return false;
    }
    const std::vector<Cell_handle> whole = group;
    const bool cut = cut_down(group);
    if (cut) {
      for (Cell_handle cell : whole) spoilt_before_[cell->info()] = 1;
    }
    return cut;
  }

 private:
  std::vector<char> spoilt_before_;  // per cell: in a group cut down before

  bool cut_down(std::vector<Cell_handle>& group) {
    std::vector<Vertex_handle> vertices, failing;
    std::vector<Cell_handle> kept, reach;
    std::unordered_map<int, char> in_group;
    for (int pass = 0; pass < 256 && !group.empty(); ++pass) {
      in_group.clear();
      for (Cell_handle cell : group) in_group[cell->info()] = 1;
      reach.clear();
      for (Cell_handle cell : group) {
        for (int i = 0; i <= D; ++i) {
          if (is_outside(cell->neighbor(i))) {
            in_group[cell->info()] = 2;
            reach.push_back(cell);
            break;
          }
        }
      }
      for (std::size_t j = 0; j < reach.size(); ++j) {
        for (int i = 0; i <= D; ++i) {
          const auto found = in_group.find(reach[j]->neighbor(i)->info());
          if (found == in_group.end() || found->second == 2) continue;
          found->second = 2;
          reach.push_back(reach[j]->neighbor(i));
        }
      }
      group.swap(reach);
      if (group.empty()) return false;
      for (Cell_handle cell : group) set_outside(cell, true);
      vertices.clear();
      for (Cell_handle cell : group) {
        for (int i = 0; i <= D; ++i) vertices.push_back(cell->vertex(i));
      }
      std::sort(vertices.begin(), vertices.end());
      vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
      failing.clear();
      for (Vertex_handle v : vertices) {
        if (solid_cells_at_[v->info()] == 0 || !manifold_at(v)) failing.push_back(v);
      }
      for (Cell_handle cell : group) set_outside(cell, false);
      if (failing.empty()) return true;
      if (pass == 0 && double(failing.size()) > spoilt_share * double(vertices.size())) {
        return false;
      }
      // At each failing vertex one cell of the group stays: the one most beside the solid
      // (facets on solid cells no longer in the group), which mends the vertex most often and
      // keeps the tunnel as wide as it can be.
      std::vector<Cell_handle> stay;
      for (Vertex_handle v : failing) {
        Cell_handle best{};
        int most = -1;
        for (Cell_handle cell : group) {
          bool at_v = false;
          for (int i = 0; i <= D; ++i) at_v = at_v || cell->vertex(i) == v;
          if (!at_v) continue;
          int beside = 0;
          for (int i = 0; i <= D; ++i) {
            const Cell_handle n = cell->neighbor(i);
            const auto found = in_group.find(n->info());
            beside += !is_outside(n) && (found == in_group.end() || found->second != 2);
          }
          if (beside > most) best = cell, most = beside;
        }
        if (most >= 0) stay.push_back(best);
      }
      kept.clear();
      for (Cell_handle cell : group) {
        if (std::find(stay.begin(), stay.end(), cell) == stay.end()) kept.push_back(cell);
      }
      group.swap(kept);
    }
    return false;
  }
};

}  // namespace sculpt
