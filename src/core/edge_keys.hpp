// SPDX-License-Identifier: GPL-3.0-or-later
// An edge of a surface as one 64-bit key: the two vertex indices packed, the smaller first for
// an undirected edge (edge_key), in order for a directed one (directed_key). The keys of the
// key tables (key_table.hpp) and sets over a surface's edges.
#pragma once

#include <cstdint>
#include <utility>

namespace sculpt {

// The same key for (a, b) and (b, a).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

// A key of the directed edge a -> b (edge_key is the undirected one).
inline std::uint64_t directed_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace sculpt
