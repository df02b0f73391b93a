// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction with every stage, as bytes and back: how a reconstruction made in the
// browser's Web Worker reaches the page (their WebAssembly instances share no memory without
// cross-origin isolation). Both ends are the same build: the bytes are the values' own, in the
// machine's order, behind a header that names the format and the dimension.
#pragma once

#include <cstdint>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt::io {

template <int D>
std::vector<std::uint8_t> to_bytes(const Reconstruction<D>& reconstruction);

// The dimension written in bytes made by to_bytes, or 0 if they are not such bytes.
int dimension_of_bytes(const std::uint8_t* bytes, std::size_t size);

// Throws io::Error for bytes that to_bytes did not make (another format, another dimension,
// cut short). The options' progress callback is not carried.
template <int D>
Reconstruction<D> reconstruction_from_bytes(const std::uint8_t* bytes, std::size_t size);

}  // namespace sculpt::io
