// SPDX-License-Identifier: GPL-3.0-or-later
// The two peers that grow a shape instead of carving one, stepped like the sculpting:
//   front: CGAL's Advancing Front adds its triangles one at a time where the front (the border
//          of what it has grown) offers the most plausible one (Front_stage);
//   alpha: the alpha shape as alpha grows, the Delaunay cells joining the solid smallest
//          circumball first (Alpha_stage), past the alpha the method chose and on.
#pragma once

#include <deque>
#include <sculpt/sculpt.hpp>
#include <string>

#include "scene/scene.hpp"

namespace sculpt::scene {

// The surface after `step` triangles (-1: all): those grown before, the step's own lit, the
// front's edges, and the samples it has not reached.
void front_growth(std::deque<Layer>& layers, Scene& scene, const Reconstruction<3>& r, long step);

// The alpha shape after `step` cells (-1: the method's own alpha): the cells in, seen whole or
// cut at the user's clip, the step's cell lit, and the samples on no cell yet.
void alpha_growth(std::deque<Layer>& layers, Scene& scene, const Reconstruction<3>& r,
                  const Request& request);

// The step under the viewer's slider: "alpha 0.243: cell 3000 of 42558 (...)".
std::string describe_growth(const Reconstruction<3>& r, Stage stage, long shown);

// How many steps each replays (the triangles; the cells).
long front_length(const Reconstruction<3>& r);
long alpha_length(const Reconstruction<3>& r);

}  // namespace sculpt::scene
