// Stages 5 and 6: choose the poles that sculpt, and insert them into the first triangulation,
// as the paper's implementation does (section 6), which turns DT(S ∪ BBV) into DT(S ∪ OUP).
//   closed:   OUP = the outer poles that are not convex (the box corners are already there);
//   bordered: UP  = every labelled pole that is not convex, on either side (section 4).
// Unlabelled poles have no side and are not inserted.
#pragma once

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
                  Reconstruction<Traits::dimension>& result, const Stage_clock& clock) {
  std::vector<Point<Traits::dimension>> centers;
  centers.reserve(result.insertion.inserted_poles.size());
  for (int pole : result.insertion.inserted_poles)
    centers.push_back(result.poles.poles[pole].center);
  const int first_site = static_cast<int>(result.sites.size());
  result.sites.insert(result.sites.end(), centers.begin(), centers.end());
  insert_in_spatial_order<Traits>(triangulation, centers, first_site, clock);
  number_cells<Traits>(triangulation, result.options.keep_triangulations, result.sculpted_delaunay);
}

}  // namespace sculpt
