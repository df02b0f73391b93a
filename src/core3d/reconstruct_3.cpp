// SPDX-License-Identifier: GPL-3.0-or-later
// The one place the 3D algorithm is compiled: everything else links against it.
#include "../driver/automatic_kind.hpp"
#include "../driver/cleaning.hpp"
#include "../driver/reconstruction.hpp"
#include "traits_3.hpp"

namespace sculpt {

Reconstruction<3> reconstruct(const std::vector<Point<3>>& samples, const Options& options) {
  return reconstruct_cleaned<3>(
      samples, options,
      [&](const std::vector<Point<3>>& given) {
        check_input<Traits_3>(given, options);
        refuse_duplicates<3>(given);
      },
      [](const std::vector<Point<3>>& points, const Options& chosen) {
        return reconstruct_choosing_kind<3>(
            chosen,
            [&](const Options& resolved, Normalised_poles<3>* keep, First_stages<3>* given) {
              return reconstruct_with<Traits_3>(points, resolved, keep, given);
            });
      });
}

}  // namespace sculpt
