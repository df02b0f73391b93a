// The paper's method, after the shared stages 1-3 (Delaunay, poles, seeds), exactly as Kuo & Yau
// publish it (sections 3.1-3.2, Fig. 5):
//   4. propagation  breadth-first pole separation by inscribed cubes and pairing
//   5. insertion    the outer concave poles OUP (UP when bordered)
//   6. sculpted     DT(S ∪ OUP), by inserting them into the first triangulation
//   7. solid        its all-sample cells
//   8. surface      the skin or the paper's extraction rule
#pragma once

#include <sculpt/sculpt.hpp>

#include "../../core/label_statistics.hpp"
#include "../../core/stage_clock.hpp"
#include "pole_insertion.hpp"
#include "pole_separation.hpp"
#include "surface_extraction.hpp"

namespace sculpt {

// Stages 5-8, from labelled poles: insert OUP (UP), then the solid and the surface.
template <class Traits>
void sculpt_by_insertion(typename Traits::Triangulation& triangulation,
                         Reconstruction<Traits::dimension>& result, Stage_clock& clock) {
  clock.start("insertion");
  choose_inserted_poles(result);
  insert_poles<Traits>(triangulation, result);
  result.stats.inserted_poles = result.insertion.inserted_poles.size();
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
  sculpt_by_insertion<Traits>(triangulation, result, clock);
}

}  // namespace sculpt
