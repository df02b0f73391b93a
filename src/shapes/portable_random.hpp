// SPDX-License-Identifier: GPL-3.0-or-later
// Random numbers that are the same on every standard library: the engine's output is fixed by
// the standard, the distributions' are not (libstdc++ natively, libc++ in the browser build), so
// the conversions are ours and the browser shows the samples the command line reconstructs.
#pragma once

#include <cmath>
#include <random>

namespace sculpt::shapes {

class Portable_random {
 public:
  explicit Portable_random(unsigned seed) : engine_(seed) {}
  double unit() { return double(engine_()) / 4294967296.0; }  // [0, 1)
  double normal() {                                           // Box-Muller, one of the pair
    const double u = 1.0 - unit(), v = unit();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2 * 3.14159265358979323846 * v);
  }

 private:
  std::mt19937 engine_;
};

}  // namespace sculpt::shapes
