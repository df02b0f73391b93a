// Stages 5 and 6: choose the poles that sculpt, and insert them into the first triangulation,
// as the paper's implementation does (section 6), which turns DT(S ∪ BBV) into DT(S ∪ OUP).
//   closed:   OUP = the outer poles that are not convex (the box corners are already there);
//   bordered: UP  = every labelled pole that is not convex, on either side (section 4).
// Unlabelled poles have no side and are not inserted.
#pragma once

#include <utility>
#include <vector>

#include "../../core/delaunay.hpp"

namespace sculpt {

template <int D>
void choose_inserted_poles(Reconstruction<D>& result) {
  const auto& labels = result.propagation.labels;
  const bool bordered = result.options.kind == Surface_kind::bordered;
  auto& inserted = result.insertion.inserted_poles;
  for (int p = 0; p < static_cast<int>(labels.size()); ++p) {
    if (result.poles.poles[p].convex || labels[p] == Label::unlabelled) continue;
    if (bordered || labels[p] == Label::outer) inserted.push_back(p);
  }
}

template <class Traits>
void insert_poles(typename Traits::Triangulation& triangulation,
                  Reconstruction<Traits::dimension>& result) {
  std::vector<std::pair<typename Traits::Cgal_point, int>> sites;
  sites.reserve(result.insertion.inserted_poles.size());
  for (int pole : result.insertion.inserted_poles) {
    const auto& center = result.poles.poles[pole].center;
    sites.emplace_back(Traits::to_cgal(center), static_cast<int>(result.sites.size()));
    result.sites.push_back(center);
  }
  triangulation.insert(sites.begin(), sites.end());  // spatially sorted, located with hints
  number_cells<Traits>(triangulation, result.options.keep_triangulations, result.sculpted_delaunay);
}

}  // namespace sculpt
