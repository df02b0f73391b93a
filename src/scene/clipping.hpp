// SPDX-License-Identifier: GPL-3.0-or-later
// A cut-away for the 3D stages that fill space (the Delaunay triangulations, the Voronoi
// diagram, the solid): everything whose centre lies beyond a plane is left out, so whole cells
// are seen in section, as mesh viewers show tetrahedra (scene::Clip says where the plane is),
// and so is what reaches far outside the samples' box (edges to the box corners).
#pragma once

#include "scene/scene.hpp"

namespace sculpt::scene {

// Leaves out the points, segments, triangles and balls whose centre lies beyond the plane (on
// the side its normal points to) or, with a slab, farther before it than the slab, or with a vertex
// (a ball: its centre) more than 5% of the box's diagonal outside the samples' box. Layers keep
// their ids: legends and toggles stay.
void clip(Scene& scene, const Clip& clip);

// The neighbourhood of one point: leaves out the primitives none of whose vertices (a ball: its
// centre) lies within `radius` of `centre`, except in the layers named `whole` (what was
// picked, shown entire). A cell edge or Voronoi edge that reaches into the neighbourhood stays.
void keep_near(Scene& scene, const Vec3& centre, float radius,
               const std::vector<std::string>& whole);

}  // namespace sculpt::scene
