// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0, cleaning: each sample moved onto the quadric (a jet of degree 2) fitted to its
// `neighbours` nearest samples, by CGAL's Point Set Processing (jet_smooth_point_set; Cazals &
// Pouget, "Estimating differential quantities using polynomial fitting of osculating jets",
// 2005). Noise across the surface is flattened out of the samples; their order is kept (sample
// i stays sample i). Compiled once, in src/core3d/jet_smoothing.cpp.
#pragma once

#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

std::vector<Point<3>> jet_smoothed(const std::vector<Point<3>>& samples, unsigned neighbours);

}  // namespace sculpt
