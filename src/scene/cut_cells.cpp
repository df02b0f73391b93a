// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/cut_cells.hpp"

#include <algorithm>
#include <cstdint>

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

}  // namespace sculpt::scene
