// SPDX-License-Identifier: GPL-3.0-or-later
// A solid of tetrahedra seen whole, or cut at a plane through whole cells (never shrunk, never
// half of them silently dropped): what shows are the faces of the kept cells that no other kept
// cell shares. A face that shows because the cell behind it was cut away lies on the section;
// the cells' edges are drawn there, where they tell the tetrahedra apart.
#pragma once

#include <array>
#include <deque>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "scene/clipping.hpp"
#include "scene/scene.hpp"

namespace sculpt::scene {

using Tetrahedron = std::array<int, 4>;
using Face = std::array<int, 3>;

struct Shown_faces {
  std::vector<Face> faces;   // every face that shows, its vertices in the cell's order
  std::vector<Face> on_cut;  // those of them whose other cell was cut away: the section
};

// The faces of `cells` that show when only the cells with `kept` set are drawn, leaving out
// those in `drawn_elsewhere` (faces with sorted vertices, sorted: another layer draws them).
Shown_faces shown_faces(const std::vector<Tetrahedron>& cells, const std::vector<bool>& kept,
                        const std::vector<Face>& drawn_elsewhere = {});

// The faces with their vertices sorted, the list sorted: what `drawn_elsewhere` takes.
std::vector<Face> sorted_faces(std::vector<Face> faces);

// A set of cells drawn whole, as one layer of shaded faces.
struct Whole_cells {
  const char* id;
  std::string label;
  Color color;
  const std::vector<Tetrahedron>* cells;
};

// The layers of a solid beside what was taken from it (the solid and carving stages): the cells
// of `solid` and then `removed` whose centroids lie before the plane (within `slab` of it, a
// share of the box, when not 0), each set's faces that show, the faces the two share drawn as
// the solid's; and the cells' edges on the cut where there are at most 2,000 cut faces, or
// always with `edges_asked` (in a thick crowd they are a dark fog).
void whole_cells_cut(std::deque<Layer>& layers, const std::vector<Point<3>>& sites,
                     const Clip_plane& plane, float slab, const Whole_cells& solid,
                     const Whole_cells& removed, bool edges_asked);

}  // namespace sculpt::scene
