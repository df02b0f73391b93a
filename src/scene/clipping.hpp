// SPDX-License-Identifier: GPL-3.0-or-later
// A cut-away for the 3D stages that fill space (the Delaunay triangulations, the Voronoi
// diagram, the solid): everything whose centre lies beyond a plane is left out, so whole cells
// are seen in section, as mesh viewers show tetrahedra (scene::Clip says where the plane is),
// and so is what reaches far outside the samples' box (edges to the box corners).
#pragma once

#include "scene/scene.hpp"

namespace sculpt::scene {

// Where a Clip puts its plane in a scene: the points p with dot(normal, p) = offset, and how far
// the samples' box reaches along the normal (`extent`: what Clip::position and slab are shares of).
struct Clip_plane {
  Vec3 normal{0, 0, 1};
  float offset = 0;
  float extent = 1;
  // Signed distance along the normal: positive beyond the plane (what the cut leaves out).
  float side(const Vec3& p) const {
    return normal[0] * p[0] + normal[1] * p[1] + normal[2] * p[2] - offset;
  }
};
Clip_plane plane_of(const Scene& scene, const Clip& clip);
Vec3 normal_of(const Clip& clip);  // the unit normal its azimuth and elevation give
// The plane across the middle facing a viewer who looks from `direction` (a shot's camera),
// as a Clip: a section of it is seen face on.
Clip facing(const Vec3& direction);

// Leaves out the points, segments, triangles and balls whose centre lies beyond the plane (on
// the side its normal points to) or, with a slab, farther before it than the slab, or with a vertex
// (a ball: its centre) more than 5% of the box's diagonal outside the samples' box. Layers keep
// their ids: legends and toggles stay. Layers already cut by whole cells (Layer::cut) are left.
void clip(Scene& scene, const Clip& clip);

// The neighbourhood of one point: leaves out the primitives none of whose vertices (a ball: its
// centre) lies within `radius` of `centre`, except in the layers named `whole` (what was
// picked, shown entire). A cell edge or Voronoi edge that reaches into the neighbourhood stays.
void keep_near(Scene& scene, const Vec3& centre, float radius,
               const std::vector<std::string>& whole);

}  // namespace sculpt::scene
