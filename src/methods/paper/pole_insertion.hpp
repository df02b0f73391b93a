// SPDX-License-Identifier: GPL-3.0-or-later
// Stages 5 and 6: choose the poles that sculpt (they become the last sites, after the samples
// and the box corners), and insert them into the first triangulation, as the paper's
// implementation does (section 6), which turns DT(S ∪ BBV) into DT(S ∪ OUP); or build that
// triangulation anew from every site (Sculpted_by, below).
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
  for (int pole : inserted) result.sites.push_back(result.poles.poles[pole].center);
  result.stats.inserted_poles = inserted.size();
}

// The sites of the chosen poles: the last of all sites.
template <int D>
std::size_t first_inserted_site(const Reconstruction<D>& result) {
  return result.sites.size() - result.insertion.inserted_poles.size();
}

// How DT(S ∪ BBV ∪ P) is made from the first triangulation. Both ways give the same
// triangulation (CGAL's is unique: a degenerate case is decided by a symbolic perturbation that
// does not depend on the order of insertion), with its cells numbered otherwise; poles at one
// point (cospherical cells share their circumcentre) are one vertex, which carries the number of
// the last of them inserted (tests/sculpted_solid_test.cpp compares the two by position).
enum class Sculpted_by {
  // P inserted into DT(S ∪ BBV), as the paper's implementation does (section 6).
  insertion,
  // Built anew from every site. Inserted, the first poles meet the huge cells DT(S ∪ BBV) has
  // outside the samples (across concavities, holes, openings) and rebuild much of them; in
  // one spatial order from the start no such cells are ever made (bunny00 as bordered: 0.52 ->
  // 0.38 s; the same below 10k points).
  rebuilding,
};

template <class Traits>
void insert_poles(typename Traits::Triangulation& triangulation,
                  Reconstruction<Traits::dimension>& result, const Stage_clock& clock,
                  Sculpted_by way = Sculpted_by::insertion) {
  if (way == Sculpted_by::rebuilding) {
    triangulation.clear();
    insert_in_spatial_order<Traits>(triangulation, result.sites, 0, clock);
  } else {
    insert_in_spatial_order<Traits>(triangulation, result.sites, first_inserted_site(result),
                                    clock);
  }
  number_cells<Traits>(triangulation, result.options.keep_triangulations, result.sculpted_delaunay);
}

}  // namespace sculpt
