// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/cut_cells.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "scene/layer_helpers.hpp"
#include "scene/palette.hpp"

namespace sculpt::scene {
namespace {

// The face opposite each corner of a tetrahedron.
constexpr int opposite[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct Face_of_cell {
  Face key;  // sorted vertices: equal for the two cells that share the face
  std::uint32_t cell;
  std::uint8_t corner;  // the face is the one opposite this corner
};

Face sorted(Face face) {
  std::sort(face.begin(), face.end());
  return face;
}

}  // namespace

std::vector<Face> sorted_faces(std::vector<Face> faces) {
  for (auto& face : faces) face = sorted(face);
  std::sort(faces.begin(), faces.end());
  return faces;
}

Shown_faces shown_faces(const std::vector<Tetrahedron>& cells, const std::vector<bool>& kept,
                        const std::vector<Face>& drawn_elsewhere) {
  std::vector<Face_of_cell> all;
  all.reserve(4 * cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (int corner = 0; corner < 4; ++corner) {
      const auto& f = opposite[corner];
      all.push_back({sorted({cells[c][f[0]], cells[c][f[1]], cells[c][f[2]]}), std::uint32_t(c),
                     std::uint8_t(corner)});
    }
  }
  std::sort(all.begin(), all.end(),
            [](const Face_of_cell& a, const Face_of_cell& b) { return a.key < b.key; });
  Shown_faces shown;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t end = i + 1;  // a face of a tetrahedrisation belongs to one or two cells
    while (end < all.size() && all[end].key == all[i].key) ++end;
    int kept_cells = 0;
    std::size_t kept_one = i;
    for (std::size_t j = i; j < end; ++j) {
      if (kept[all[j].cell]) ++kept_cells, kept_one = j;
    }
    if (kept_cells == 1 &&
        !std::binary_search(drawn_elsewhere.begin(), drawn_elsewhere.end(), all[i].key)) {
      const auto& cell = cells[all[kept_one].cell];
      const auto& f = opposite[all[kept_one].corner];
      const Face face{cell[f[0]], cell[f[1]], cell[f[2]]};
      shown.faces.push_back(face);
      if (end - i > 1) shown.on_cut.push_back(face);
    }
    i = end;
  }
  return shown;
}

namespace {

Vec3 position(const Point<3>& p) {
  return {float(p[0]), float(p[1]), float(p[2])};
}

std::vector<bool> before_the_plane(const std::vector<Tetrahedron>& cells,
                                   const std::vector<Point<3>>& sites, const Clip_plane& plane,
                                   float slab) {
  std::vector<bool> kept(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    Vec3 centroid{0, 0, 0};
    for (int v : cells[c]) {
      const Vec3 p = position(sites[v]);
      for (int k = 0; k < 3; ++k) centroid[k] += p[k] / 4;
    }
    const float side = plane.side(centroid);
    kept[c] = side <= 0 && (slab <= 0 || side >= -slab * plane.extent);
  }
  return kept;
}

void faces_layer(std::deque<Layer>& layers, const std::vector<Point<3>>& sites,
                 const std::vector<Face>& faces, const Whole_cells& set) {
  Layer& layer = add_layer(layers, set.id, set.label, Primitive::triangles, set.color, 1.0f);
  layer.lit = true;
  layer.cut = true;
  for (const auto& face : faces) {
    for (int v : face) layer.positions.push_back(position(sites[v]));
  }
}

}  // namespace

void whole_cells_cut(std::deque<Layer>& layers, const std::vector<Point<3>>& sites,
                     const Clip_plane& plane, float slab, const Whole_cells& solid,
                     const Whole_cells& removed, bool edges_asked) {
  const Shown_faces kept =
      shown_faces(*solid.cells, before_the_plane(*solid.cells, sites, plane, slab));
  faces_layer(layers, sites, kept.faces, solid);
  std::vector<Face> on_cut = kept.on_cut;
  if (!removed.cells->empty()) {
    // The faces between the solid and what was taken away are the solid's to draw.
    const Shown_faces away =
        shown_faces(*removed.cells, before_the_plane(*removed.cells, sites, plane, slab),
                    sorted_faces(kept.faces));
    faces_layer(layers, sites, away.faces, removed);
    on_cut.insert(on_cut.end(), away.on_cut.begin(), away.on_cut.end());
  }
  // A few thousand cut cells' edges tell the tetrahedra apart; more are a dark fog.
  if (on_cut.empty() || (on_cut.size() > 2000 && !edges_asked)) return;
  Layer& edges = add_layer(layers, "cut-cells", "edges of the cells cut", Primitive::lines,
                           palette::cut_cell_edge, 1.0f);
  edges.cut = true;
  std::vector<std::pair<int, int>> pairs;
  for (const auto& f : on_cut) {
    for (int i = 0; i < 3; ++i) pairs.push_back(std::minmax(f[i], f[(i + 1) % 3]));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& [a, b] : pairs) {
    edges.positions.push_back(position(sites[a]));
    edges.positions.push_back(position(sites[b]));
  }
}

}  // namespace sculpt::scene
