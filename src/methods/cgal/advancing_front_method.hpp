// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's Advancing Front Surface Reconstruction (Cohen-Steiner & Da, 2004), as a method beside
// the others: it grows a surface from a seed triangle of its own Delaunay triangulation,
// adding at each border edge the candidate triangle of smallest radius that keeps the surface an
// oriented 2-manifold, so it never makes a non-manifold edge but may leave holes. It builds its
// triangulation itself (CGAL gives no way to hand it ours); stages 1 and 2 are computed only
// where triangulations are kept, so that the viewer shows the same Delaunay triangulation for
// every method (stage_plan.hpp).
//
// CGAL's Advancing Front breaks some ties by memory address: on noisy input its surface can
// change by a few triangles with the process's memory layout (measured on a noisy cap: 3 or 4
// samples left off under different malloc settings, the same build), so the viewer's surface
// and the command line's may differ there. Each is repeatable run to run.
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

#include "../../core/canonical_order.hpp"
#include "../../core/stage_clock.hpp"
#include "outward_orientation.hpp"

namespace sculpt {

// The call itself is the benchmark's yardstick (src/yardsticks), on our normalised samples.
inline void run_advancing_front_method(Reconstruction<3>& result, Stage_clock& clock) {
  clock.start("advancing-front");
  const auto n = static_cast<std::ptrdiff_t>(result.sample_count());
  result.surface = cgal_advancing_front({result.sites.begin(), result.sites.begin() + n});
  orient_outward(result.sites, result.surface);
  put_in_canonical_order(result.surface);
}

}  // namespace sculpt
