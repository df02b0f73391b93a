// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's method, after the shared stages 1-3 (Delaunay, poles, seeds), exactly as Kuo & Yau
// publish it (sections 3.1-3.2, Fig. 5):
//   4. propagation  breadth-first pole separation by inscribed cubes and pairing
//   5. insertion    the outer concave poles OUP (UP when bordered)
//   6. sculpted     DT(S ∪ OUP), by inserting them into the first triangulation
//   7. solid        its all-sample cells
//   8. surface      the skin or the paper's extraction rule
// When nobody asks to see DT(S ∪ OUP) (the command line) and the surface is a closed skin,
// stages 6-7 are answered on the first triangulation instead (solid_by_queries.hpp): the same
// solid and surface, without the insertion.
#pragma once

#include <sculpt/sculpt.hpp>

#include "../../core/label_statistics.hpp"
#include "../../core/solid_and_skin.hpp"
#include "../../core/stage_clock.hpp"
#include "../../core/stage_plan.hpp"
#include "pole_insertion.hpp"
#include "pole_separation.hpp"
#include "solid_by_queries.hpp"
#include "surface_extraction.hpp"

namespace sculpt {

// Stages 5-8, from labelled poles: OUP (UP) inserted or queried, then the solid and the surface.
// (The paper's method inserts, as its authors did; the robust method, whose surfaces do not
// depend on the numbering of the cells, rebuilds.)
template <class Traits>
void sculpt_with_poles(typename Traits::Triangulation& triangulation,
                       Reconstruction<Traits::dimension>& result, Stage_clock& clock,
                       Sculpted_by way = Sculpted_by::insertion) {
  if (!builds_sculpted_delaunay(result.options)) {
    clock.start("queries");
    choose_inserted_poles(result);
    const auto solid = solid_cells_by_queries<Traits>(triangulation, result, clock);
    const auto in_solid = [&](typename Traits::Cell_handle cell) {
      return solid[cell->info()] != 0;
    };
    clock.start("solid");
    collect_solid<Traits>(triangulation, in_solid, result);
    clock.start("surface");
    collect_skin<Traits>(triangulation, in_solid, result);
    return;
  }
  clock.start("insertion");
  choose_inserted_poles(result);
  insert_poles<Traits>(triangulation, result, clock, way);
  result.stats.sculpted_cells = result.sculpted_delaunay.cell_count;

  clock.start("solid");
  sculpt_solid<Traits>(triangulation, result);

  clock.start("surface");
  extract_surface<Traits>(triangulation, result);
}

template <class Traits>
void run_paper_method(typename Traits::Triangulation& triangulation,
                      Reconstruction<Traits::dimension>& result, Stage_clock& clock) {
  clock.start("propagation");
  propagate_labels(result, clock);
  count_labels(result);
  sculpt_with_poles<Traits>(triangulation, result, clock);
}

}  // namespace sculpt
