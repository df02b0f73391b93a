// SPDX-License-Identifier: GPL-3.0-or-later
// The one place the 2D algorithm is compiled: everything else links against it.
#include "../driver/automatic_kind.hpp"
#include "../driver/cleaning.hpp"
#include "../driver/reconstruction.hpp"
#include "traits_2.hpp"

namespace sculpt {

Reconstruction<2> reconstruct(const std::vector<Point<2>>& samples, const Options& options) {
  return reconstruct_cleaned<2>(
      samples, options,
      [&](const std::vector<Point<2>>& given) {
        check_input<Traits_2>(given, options);
        refuse_duplicates<2>(given);
      },
      [](const std::vector<Point<2>>& points, const Options& chosen) {
        return reconstruct_choosing_kind<2>(
            chosen,
            [&](const Options& resolved, Normalised_poles<2>* keep, First_stages<2>* given) {
              return reconstruct_with<Traits_2>(points, resolved, keep, given);
            });
      });
}

}  // namespace sculpt
