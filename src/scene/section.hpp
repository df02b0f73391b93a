// SPDX-License-Identifier: GPL-3.0-or-later
// A true section of a 3D stage: what a plane cuts, drawn in the plane. Each cell the plane
// crosses becomes the polygon of its cut (a triangle or a quadrilateral), filled by what the
// cell is at that stage (inside the hull or outside it, kept or sculpted away); the Voronoi
// diagram becomes the segments where its faces cross the plane; a surface becomes the curve
// where it does; the samples and poles near the plane are laid on it. Seen along the plane's
// normal, a 3D triangulation reads as a 2D one, as the paper's Figs. 1 and 2 draw it.
#pragma once

#include <array>
#include <vector>

#include "scene/clipping.hpp"
#include "scene/scene.hpp"

namespace sculpt::scene {

// Appends the cut of one tetrahedron: its polygon as triangles to `fill` and its sides as
// segments to `outline`. Nothing when the plane misses it.
void cut_tetrahedron(const std::array<Vec3, 4>& corners, const Clip_plane& plane,
                     std::vector<Vec3>& fill, std::vector<Vec3>& outline);

// Appends the segment where the plane crosses a triangle, if it does.
void cut_triangle(const std::array<Vec3, 3>& corners, const Clip_plane& plane,
                  std::vector<Vec3>& segments);

// The scene of a 3D stage in section at the plane request.clip (Request::sectioned).
Scene build_section(const Reconstruction<3>& reconstruction, const Request& request);

}  // namespace sculpt::scene
