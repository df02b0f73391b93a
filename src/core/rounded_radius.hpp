// Squared radii kept as floats, for orders and bounds that need not be exact: half the memory of
// doubles for one number per Delaunay cell.
#pragma once

#include <limits>

namespace sculpt {

// Beyond the float range (a nearly flat cell's huge ball): infinity, not an undefined conversion.
inline float rounded_to_float(double squared_radius) {
  return squared_radius < double(std::numeric_limits<float>::max())
             ? static_cast<float>(squared_radius)
             : std::numeric_limits<float>::infinity();
}

// A number surely at least the double that was rounded to `rounded`: rounding to nearest is off
// by at most 2^-24 of the value in the normal range; below it (tiny balls of nearly coincident
// samples) nothing is sure, so infinity.
inline double at_least_the_rounded(float rounded) {
  return rounded >= std::numeric_limits<float>::min() ? double(rounded) * (1 + 1e-6)
                                                      : std::numeric_limits<double>::infinity();
}

}  // namespace sculpt
