// Each method's pseudo-code, in the order our implementation runs it (the paper method: its
// Fig. 5), and which line a moment of the algorithm is at.
#pragma once

#include <vector>

#include "scene/scene.hpp"

namespace sculpt::frontend {

inline const std::vector<const char*>& robust_pseudo_code() {
  static const std::vector<const char*> lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",
      "OSP <- convex poles: outer, weight 1",
      "heap <- OSP   # largest |outer - inner| first",
      "while heap not empty:",
      "    p <- most confident pole; label it",
      "    for q whose ball meets B(p) at s:",
      "        ev(q, label p) max= cos(p s q)",
      "    for q paired with p (antipodal):",
      "        ev(q, other side) max= -cos(p s q)",
      "outer(c) <- OUP in ball(c) or power(c) outer",
      "carve outer c from outside, if manifold",
      "open cavities, handles; expose samples",
      "solid <- cells left",
      "surface <- facets solid | outside",
  };
  return lines;
}

// The line to highlight in the robust method's pseudo-code.
inline int robust_current_line(scene::Stage stage, const Labelling_event* latest) {
  switch (stage) {
    case scene::Stage::samples:
    case scene::Stage::delaunay:
    case scene::Stage::hull:
    case scene::Stage::voronoi:
      return 0;
    case scene::Stage::poles:
      return 2;
    case scene::Stage::seeds:
      return 3;
    case scene::Stage::propagation:
      if (!latest) return 4;
      if (latest->reason == Label_reason::convex_seed) return 3;
      return latest->reason == Label_reason::pairing ? 10 : 8;
    case scene::Stage::outer_concave:
      return 11;
    case scene::Stage::sculpted_delaunay:
      return 12;
    case scene::Stage::solid:
      return 14;
    case scene::Stage::surface:
      return 15;
  }
  return 0;
}

inline const std::vector<const char*>& pseudo_code() {
  static const std::vector<const char*> lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    p+(s) <- farthest vertex of Vor(s)",
      "    p-(s) <- farthest v, (v-s).(p+ -s) < 0",
      "OSP <- convex poles: outer",
      "ISP <- poles paired with OSP: inner",
      "queue <- OSP, ISP",
      "while queue not empty:",
      "    p <- pop(queue)",
      "    for q in kd-range(cube in B(p)):",
      "        label q like p",
      "    for q paired with p:",
      "        label q opposite p",
      "OUP <- outer poles that are not convex",
      "DT <- insert(DT, OUP)",
      "solid <- cells whose vertices are all in S",
      "surface <- facets solid | rest",
  };
  return lines;
}

// The line to highlight for a stage; in the propagation, the line of the latest event's reason.
inline int current_line(scene::Stage stage, const Labelling_event* latest) {
  switch (stage) {
    case scene::Stage::samples:
    case scene::Stage::delaunay:
    case scene::Stage::hull:
    case scene::Stage::voronoi:
      return 0;
    case scene::Stage::poles:
      return 2;
    case scene::Stage::seeds:
      return 4;
    case scene::Stage::propagation:
      if (!latest) return 6;
      if (latest->reason == Label_reason::convex_seed) return 4;
      if (latest->reason == Label_reason::inscribed_cube) return 10;
      return 12;
    case scene::Stage::outer_concave:
      return 13;
    case scene::Stage::sculpted_delaunay:
      return 14;
    case scene::Stage::solid:
      return 15;
    case scene::Stage::surface:
      return 16;
  }
  return 0;
}

}  // namespace sculpt::frontend
