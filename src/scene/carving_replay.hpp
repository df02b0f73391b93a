// SPDX-License-Identifier: GPL-3.0-or-later
// The sculpting replayed: the hull's cells (the all-sample cells of DT(S ∪ BBV), stage 1)
// leaving it step by step, as each method takes them away; Kuo & Yau's Figs. 1 and 2 as a film.
//  - The paper method inserts the outer concave poles (sec. 3.3, "DT <- insert(DT, OUP)"). A
//    pole inserted into a Delaunay triangulation destroys the cells whose circumballs hold it,
//    so each step inserts one pole and the hull's cells still there whose circumballs hold it
//    leave. Any order of insertion ends at the same DT(S ∪ OUP); the replay takes the order of
//    the list (stage 5). The robust method's bordered surfaces insert poles the same way.
//  - The robust method's carving and Boissonnat's removal take one cell per step, in the order
//    they recorded it (stage 6b), each with its reason; a removal of several cells at once (an
//    opening, the only kind of step that can change the topology) is one step.
// The replay always ends at the solid: a hull cell not in the solid that no step took (a tie on
// a circumsphere, in doubles) leaves at a last step of its own, and a solid cell never leaves.
#pragma once

#include <cstdint>
#include <memory>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sculpt::scene {

struct Carving_step {
  std::vector<int> cells;  // the cells that leave, indices into stage 1's cells
  int pole = -1;           // the pole inserted (an index into the poles), when poles are
  Carve_reason reason = Carve_reason::outer_pole_inside;  // when cells are carved
  // The robust carving's removals of several cells at once (solid_openings.hpp) are one step
  // each: the opening's index into Carving_stage::openings (-1: a cell removed on its own).
  int opening = -1;
};

struct Carving_replay {
  std::vector<int> hull;  // stage 1's all-sample cells, the replay's start
  std::vector<Carving_step> steps;
  bool by_poles = false;           // steps insert poles (else: carve cells one by one)
  std::size_t inserted_poles = 0;  // by poles: how many were inserted, destroying hull cells or not
};

// Whether the method's replay carves anything here (bordered robust curves join neighbours).
bool carves_cells(Method method, Surface_kind kind, int dimension);

// Needs the triangulations kept (Options::keep_triangulations); throws std::invalid_argument
// without them.
template <int D>
Carving_replay carving_replay(const Reconstruction<D>& reconstruction);

// The same, computed once for a reconstruction and kept while it is among the last four asked
// about: a replay played in the viewer builds a scene at every step, in every view compared.
template <int D>
std::shared_ptr<const Carving_replay> shared_carving_replay(
    const Reconstruction<D>& reconstruction);

// The steps of a stage that replays (the labelling's events, the carving's steps, the pruning's
// triangles); 0 for a stage that does not.
long replay_length(const Reconstruction<2>& reconstruction, Stage stage);
long replay_length(const Reconstruction<3>& reconstruction, Stage stage);

// What each of stage 1's cells is after the first `step` steps (-1: all of them), for the
// pictures of that moment; `shown` is the steps done.
enum class Cell_state : std::uint8_t { outside_hull, kept, taken_before, taken_now };
struct Carving_moment {
  std::size_t shown = 0;
  std::vector<Cell_state> states;  // by stage 1's cell index
};
Carving_moment moment_of(const Carving_replay& replay, std::size_t cell_count, long step);

// A short line on a carving step, for titles and the viewer: "step 12 of 65: a pole destroys 2
// triangles", "step 5 of 812: outer pole in its circumball", "step 700 of 812: a web of outer
// cells punched through, 7 tetrahedra at once: a handle opens".
std::string describe_step(const Carving_replay& replay, std::size_t step, int dimension,
                          const Carving_stage& carving);

}  // namespace sculpt::scene
