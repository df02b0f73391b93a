// SPDX-License-Identifier: GPL-3.0-or-later
// The handles a closed surface has that its samples cannot vouch for.
//
// A closed surface of genus g has 2g independent loops that bound no piece of it: around each
// handle, and through it. Where a handle (or the tunnel beside it) is thinner than the samples'
// spacing, one of them is short: a loop through only three or four samples, a neck that no
// sample lies around, which the sampling cannot tell from a gap (two sheets that touch, a wall
// punched through). Those loops are the evidence this stage looks for, in every method's result:
//   - candidates: cycles of three or four of the surface's edges, with no chord, that are not
//     the border of its triangles, and whose longest edge is at most thin_neck times the
//     spacing of its samples (their mean distance to their nearest neighbour on the surface);
//   - kept: a candidate independent of those kept before, that is, cutting the surface along all
//     of them leaves it connected (found by flooding from both sides of the new loop at once, so
//     that a loop around a small disc is rejected after a few triangles).
// Triangles not oriented alike (two that both go a -> b) are not searched.
// A candidate through a sample of a loop kept is passed over (the count stays exact for loops
// that share no sample), and the search stops at the genus: the count is a lower bound of the
// handles so thin, and each loop kept is drawn where it is.
#pragma once

#include <array>
#include <cstddef>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

/// A loop's longest edge may be this many times the spacing around it, and the loop is thin.
/// (The sides of a triangle of evenly spaced samples are 1-1.5 times their nearest distance.)
inline constexpr double thin_neck = 2.0;

/// The thin handles of a closed 2-manifold (every edge on two triangles, consistently oriented)
/// of the given genus (summed over its components), at most `genus` of them; none for genus 0.
/// `points` are the triangles' vertices.
std::vector<Thin_handle> find_thin_handles(const std::vector<Point<3>>& points,
                                           const std::vector<Facet<3>>& triangles,
                                           std::size_t genus);

/// The thin handles of a result that is a closed 2-manifold of positive genus: into
/// result.thin_handles and its count into the statistics.
void find_thin_handles_of(Reconstruction<3>& result);

}  // namespace sculpt
