// SPDX-License-Identifier: GPL-3.0-or-later
// The one place the 3D algorithm is compiled: everything else links against it.
#include "../driver/automatic_kind.hpp"
#include "../driver/reconstruction.hpp"
#include "traits_3.hpp"

namespace sculpt {

Reconstruction<3> reconstruct(const std::vector<Point<3>>& samples, const Options& options) {
  return reconstruct_choosing_kind<3>(
      options, [&](const Options& resolved, Normalised_poles<3>* keep, First_stages<3>* given) {
        return reconstruct_with<Traits_3>(samples, resolved, keep, given);
      });
}

}  // namespace sculpt
