// SPDX-License-Identifier: GPL-3.0-or-later
// Where a surface's handles rest on thin evidence, drawn on the result (the surface stage):
//  - the loops around (or through) handles thinner than the samples' spacing, which the result
//    has: where its genus is a guess the sampling cannot check (core/thin_handles.hpp);
//  - the cells where the robust carving refused to punch a handle through a web one sample
//    thin, which the result has not (methods/robust/solid_openings.hpp): their edges.
#pragma once

#include <deque>
#include <sculpt/sculpt.hpp>
#include <string>

#include "layer_helpers.hpp"
#include "palette.hpp"
#include "scene.hpp"

namespace sculpt::scene {

template <int D>
void add_handle_layers(std::deque<Layer>& layers, const Reconstruction<D>& r) {
  if constexpr (D == 3) {
    if (!r.thin_handles.empty()) {
      Layer& layer = add_layer(layers, "thin-handles",
                               "suspect handles, thinner than the spacing (" +
                                   std::to_string(r.thin_handles.size()) + ")",
                               Primitive::lines, palette::thin_handle, 4.0f);
      for (const auto& handle : r.thin_handles) {
        const int k = handle.loop[3] < 0 ? 3 : 4;
        for (int j = 0; j < k; ++j) {
          layer.positions.push_back(vec(r.surface_points()[handle.loop[j]]));
          layer.positions.push_back(vec(r.surface_points()[handle.loop[(j + 1) % k]]));
        }
      }
    }
    // The cells are kept with the triangulations only.
    const auto& refused = r.carving.refused_handles;
    if (refused.empty() || r.delaunay.cells.size() != r.delaunay.cell_count) return;
    Layer& layer = add_layer(
        layers, "refused-handles",
        "handles refused, webs kept (" + std::to_string(r.stats.refused_handles) + ")",
        Primitive::lines, palette::refused_handle, 3.0f);
    for (int cell : refused) {
      const auto& sites = r.delaunay.cells[std::size_t(cell)];
      for (int i = 0; i <= D; ++i) {
        for (int j = i + 1; j <= D; ++j) {
          layer.positions.push_back(vec(r.sites[sites[i]]));
          layer.positions.push_back(vec(r.sites[sites[j]]));
        }
      }
    }
  }
}

}  // namespace sculpt::scene
