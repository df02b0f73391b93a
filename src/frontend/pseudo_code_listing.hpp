// SPDX-License-Identifier: GPL-3.0-or-later
// What every method's pseudo-code is made of: its lines, and which of them each stage and each
// labelling event runs; the stages before the labelling, and the confidence labelling the robust
// method and the power crust share, written once.
#pragma once

#include <map>
#include <vector>

#include "scene/scene.hpp"

namespace sculpt::frontend {

// The statements a moment runs, by their first lines, the main one first. The viewer also
// lights each statement's continuation lines and the loop headers around it (statement_block).
using Line_list = std::vector<int>;

struct Pseudo_code {
  std::vector<const char*> lines;
  std::map<scene::Stage, Line_list> lines_of_stage;
  std::map<Label_reason, Line_list> lines_of_reason;  // in the propagation: the latest event's
  Line_list before_any_event = {0};                   // in the propagation, before any event
  // In the propagation: a convex seed's partner labelled by the pairing (the paper's ISP);
  // empty where the method has no line of its own for it.
  Line_list seed_partner;
  // In the propagation: the line of a conflict (a label offered against the one a pole has),
  // shown when one follows the event on screen; -1 for a method without conflicts.
  int conflict_line = -1;
};

// The stages before the labelling show the first line or the poles' lines in every method.
inline std::map<scene::Stage, Line_list> common_stage_lines(Line_list poles_lines) {
  using scene::Stage;
  return {{Stage::samples, {0}},
          {Stage::delaunay, {0}},
          {Stage::hull, {0}},
          {Stage::voronoi, {0}},
          {Stage::poles, poles_lines}};
}

// The confidence labelling the robust method and the power crust share
// (src/methods/robust/confidence_labelling.hpp), after the poles: its lines and their places.
inline void add_confidence_labelling_lines(Pseudo_code& code) {
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",     "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",        "OSP <- convex poles: outer, weight 1",
      "heap <- OSP  # largest |outer-inner| first", "while heap not empty:",
      "    p <- most confident pole; label it",     "    for q whose ball meets B(p) at s:",
      "        ev(q, label p) max= cos(p s q)",     "    for q paired with p (antipodal):",
      "        ev(q, other side) max= -cos(p s q)", "    ev >= .5 against q's label: contradicted",
  };
  code.lines_of_stage = common_stage_lines({2});
  code.lines_of_stage.insert({scene::Stage::seeds, {3}});
  code.lines_of_reason = {{Label_reason::convex_seed, {6, 3}},
                          {Label_reason::ball_overlap, {8, 6}},
                          {Label_reason::pairing, {10, 6}},
                          {Label_reason::inscribed_cube, {8, 6}}};
  code.before_any_event = {4};
  code.conflict_line = 11;
}

}  // namespace sculpt::frontend
