// SPDX-License-Identifier: GPL-3.0-or-later
// How much one input may hold. A pipe or a device can be endless, and a file of short lines
// holds far more points than its bytes suggest (6 bytes of "0 0 0\n" become 24 bytes of a
// point): so an input is read against a budget on its bytes and one on its points, whatever it
// is. Both are far beyond what a reconstruction fits in memory, and both can be raised:
//   SCULPT_MAX_INPUT_BYTES  default 4 GiB
//   SCULPT_MAX_POINTS       default 50,000,000 points (a mesh's faces: four per point)
// Every refusal names the limit and the variable that raises it.
#pragma once

#include <cstdint>
#include <string>

namespace sculpt::io {

struct Input_limits {
  std::uint64_t bytes = std::uint64_t(4) << 30;
  // A 3D reconstruction holds about 1 KB per sample (its Delaunay triangulation has some
  // 6.5 tetrahedra per point, then poles and labels): 50 million samples would need some 50 GB.
  std::uint64_t points = 50'000'000;
  // Polygons split into triangles; at most INT_MAX, as the points (input_limits() says so).
  std::uint64_t faces() const { return points > (UINT64_MAX >> 2) ? UINT64_MAX : 4 * points; }
};

// The defaults, or what the environment sets. Throws io::Error for a value that is not a whole
// number above zero.
Input_limits input_limits();

// A size for messages: "4 GiB", "12 MiB" (rounded down), "4567 bytes".
std::string size_text(std::uint64_t bytes);

// The end of a refusal: "the input limit of 50000000 points (SCULPT_MAX_POINTS raises it)".
std::string points_limit_text(std::uint64_t points);
std::string bytes_limit_text(std::uint64_t bytes);

}  // namespace sculpt::io
