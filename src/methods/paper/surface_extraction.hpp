// SPDX-License-Identifier: GPL-3.0-or-later
// Stages 7 and 8 (section 3.2): the sculpted solid and the surface, read off DT(S ∪ OUP).
//
// Every facet whose vertices are all samples has two apexes, the vertices opposite it in its two
// cells. An apex is on the outer side if it is an outer pole, a box corner or CGAL's infinite
// vertex, and on the inner side if it is a sample (the cell is part of the solid) or an inner
// pole (only inserted for bordered surfaces).
//   sculpting rule:  the solid is the cells whose vertices are all samples;
//   skin:            facets with one apex on each side, i.e. the solid's boundary when closed;
//   extraction rule: facets with at least one outer apex (the paper's literal rule).
// Facets are oriented to face their outer apex: outward, for a closed surface.
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/solid_and_skin.hpp"

namespace sculpt {

template <class Traits>
class Apex_sides {
 public:
  explicit Apex_sides(const Reconstruction<Traits::dimension>& result)
      : result_(result), sample_count_(static_cast<int>(result.sample_count())) {}

  bool is_sample(typename Traits::Triangulation::Vertex_handle v) const {
    return v->info() < sample_count_;
  }

  bool is_outer(const typename Traits::Triangulation& triangulation,
                typename Traits::Triangulation::Vertex_handle v) const {
    if (triangulation.is_infinite(v)) return true;
    switch (result_.kind_of_site(v->info())) {
      case Site_kind::sample:
        return false;
      case Site_kind::box_corner:
        return true;
      case Site_kind::pole:
        return result_.propagation.labels[result_.pole_of_site(v->info())] == Label::outer;
    }
    return false;
  }

 private:
  const Reconstruction<Traits::dimension>& result_;
  int sample_count_;
};

template <class Traits>
void sculpt_solid(const typename Traits::Triangulation& triangulation,
                  Reconstruction<Traits::dimension>& result) {
  const Apex_sides<Traits> sides(result);
  const auto all_samples = [&](typename Traits::Cell_handle cell) {
    for (int i = 0; i <= Traits::dimension; ++i) {
      if (!sides.is_sample(cell->vertex(i))) return false;
    }
    return true;
  };
  collect_solid<Traits>(triangulation, all_samples, result);
}

template <class Traits>
void extract_surface(const typename Traits::Triangulation& triangulation,
                     Reconstruction<Traits::dimension>& result) {
  constexpr int D = Traits::dimension;
  const Apex_sides<Traits> sides(result);
  const bool literal_rule = resolved_rule(result.options) == Surface_rule::extraction;
  for (auto cell : Traits::all_cells(triangulation)) {
    for (int i = 0; i <= D; ++i) {
      Facet<D> facet;
      bool all_samples = true;
      for (int j = 0; j < D && all_samples; ++j) {
        const auto v = cell->vertex(Traits::facet_vertex[i][j]);
        all_samples = !triangulation.is_infinite(v) && sides.is_sample(v);
        if (all_samples) facet[j] = v->info();
      }
      if (!all_samples) continue;
      const auto neighbor = cell->neighbor(i);
      const auto apex = cell->vertex(i);
      const auto other_apex = neighbor->vertex(neighbor->index(cell));
      if (!sides.is_outer(triangulation, other_apex)) continue;  // face the outer apex
      const bool apex_outer = sides.is_outer(triangulation, apex);
      // Each facet is seen from both of its cells: with one outer apex it is emitted from the
      // inner cell; with two (extraction rule only), once, from the lower-addressed cell.
      const bool emit = !apex_outer || (literal_rule && cell->info() < neighbor->info());
      if (emit) result.surface.push_back(facet);
    }
  }
}

}  // namespace sculpt
