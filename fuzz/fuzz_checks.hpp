// SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzzers check on every input, shared with the suite that replays the inputs that
// once failed (tests/fuzz_regressions_test.cpp), so a regression fails in every build.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sculpt/sculpt.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "io/point_reader.hpp"

namespace sculpt::fuzz {

// Any bytes give points or an io::Error with a one-line message, never another exception; the
// bytes read whole and handed over in small chunks (as a pipe does) give the same points,
// faces, normals and colours; normals and colours are given for every point or none. Returns
// what went wrong, or "" (a crash or sanitizer report never returns).
inline std::string check_reader(std::string_view bytes, const std::string& format) {
  struct Outcome {
    io::Point_set set;
    std::string error;
  };
  const auto read = [&](std::size_t chunk) {
    Outcome outcome;
    try {
      outcome.set = io::read_points_from_memory(bytes, format, chunk);
    } catch (const io::Error& e) {
      outcome.error = e.what();
    }
    return outcome;
  };
  const Outcome whole = read(0), chunked = read(1 + bytes.size() % 7);
  if (whole.error.find('\n') != std::string::npos) return "a message of more than one line";
  if (whole.error != chunked.error || whole.set.points != chunked.set.points ||
      whole.set.triangles != chunked.set.triangles ||
      whole.set.attributes.normals != chunked.set.attributes.normals ||
      whole.set.attributes.colors != chunked.set.attributes.colors) {
    return "whole and chunked reads differ: '" + whole.error + "' / '" + chunked.error + "'";
  }
  // Normals and colours are for every point or none.
  const std::size_t points = whole.set.points.size();
  for (std::size_t given :
       {whole.set.attributes.normals.size(), whole.set.attributes.colors.size()}) {
    if (given != 0 && given != points) return "attributes for some points only";
  }
  return "";
}

// The reconstruction on tiny inputs (at most 64 points). The first byte picks the dimension,
// method, kind and whether the triangulations are kept; then each point is D signed bytes on a
// coarse grid (duplicates, collinear, coplanar, cocircular and cospherical sets are common) or,
// with the top bit of the first byte, D raw doubles (any bits: NaN, infinities, denormals).
// A result or an Input_error, never a crash, undefined behaviour or another exception. For the
// paper method's closed surfaces, the solid and surface read off DT(S ∪ BBV) by circumball
// queries (triangulations not kept) must be the insertion's (kept), cell for cell.
template <int D>
void expect_queries_match_insertion(const std::vector<Point<D>>& points, Options options,
                                    const Reconstruction<D>& first) {
  options.keep_triangulations = !options.keep_triangulations;
  const Reconstruction<D> second = reconstruct(points, options);
  const auto cells = [](std::vector<Cell<D>> c) {
    for (auto& cell : c) std::sort(cell.begin(), cell.end());
    std::sort(c.begin(), c.end());
    return c;
  };
  const auto facets = [](std::vector<Facet<D>> f) {
    for (auto& facet : f)
      std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
    std::sort(f.begin(), f.end());
    return f;
  };
  if (cells(first.solid) != cells(second.solid) ||
      facets(first.surface) != facets(second.surface)) {
    std::fprintf(stderr, "the paper's solid by queries differs from the solid by insertion\n");
    std::abort();
  }
}

template <int D>
void reconstruct_points(const std::uint8_t* data, std::size_t size, const Options& options,
                        bool raw) {
  std::vector<Point<D>> points;
  const std::size_t stride = raw ? D * sizeof(double) : D;
  for (std::size_t at = 0; at + stride <= size && points.size() < 64; at += stride) {
    Point<D> p{};
    for (int k = 0; k < D; ++k) {
      if (raw) {
        std::memcpy(&p[k], data + at + k * sizeof(double), sizeof(double));
      } else {
        p[k] = static_cast<std::int8_t>(data[at + k]) / 8.0;
      }
    }
    points.push_back(p);
  }
  try {
    const Reconstruction<D> result = reconstruct(points, options);
    (void)verdict(result.stats);
    if (options.method == Method::paper && options.kind == Surface_kind::closed) {
      expect_queries_match_insertion<D>(points, options, result);
    }
  } catch (const Input_error&) {
    // refused with a message: the contract for input that cannot be reconstructed
  }
}

inline void check_reconstruction(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  const std::uint8_t mode = data[0];
  Options options;
  options.method = (mode & 1) ? Method::paper : Method::robust;
  options.kind = (mode & 2) ? Surface_kind::bordered : Surface_kind::closed;
  options.keep_triangulations = (mode & 8) != 0;
  const bool raw = (mode & 128) != 0;
  if (mode & 4) {
    reconstruct_points<3>(data + 1, size - 1, options, raw);
  } else {
    reconstruct_points<2>(data + 1, size - 1, options, raw);
  }
}

}  // namespace sculpt::fuzz
