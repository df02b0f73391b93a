// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a piece of the solid that a removal would cut off is a part of the shape in its own
// right, by the labelling's evidence: most of its samples have an inner pole in it. The medial
// balls of a separate curve (2D) or a small separate part lie inside it, so its samples' inner
// poles are cells of the piece; a sliver or bubble left by mislabelled cells holds the inner
// poles of few of its samples, whose insides are elsewhere. (A sample's poles are Delaunay cells
// around it, so an inner pole cell of a sample in the piece that is still in the solid is in the
// sample's piece, short of a pinch.)
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

// `samples`: the piece's samples (each once). `in_piece(cell)`: whether the cell numbered so
// belongs to the piece.
template <int D, class In_piece>
bool holds_inner_poles_of_most(const Reconstruction<D>& result, const std::vector<int>& samples,
                               In_piece&& in_piece) {
  std::size_t with_inside = 0;
  for (int s : samples) {
    for (int q : {result.poles.positive_pole[s], result.poles.negative_pole[s]}) {
      if (q >= 0 && result.propagation.labels[q] == Label::inner &&
          in_piece(result.poles.poles[q].cell)) {
        ++with_inside;
        break;
      }
    }
  }
  return !samples.empty() && 2 * with_inside >= samples.size();
}

}  // namespace sculpt
