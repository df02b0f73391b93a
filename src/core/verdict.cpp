// SPDX-License-Identifier: GPL-3.0-or-later
// The verdict on a result: one line that says whether it is what was asked for (a closed
// 2-manifold or closed curves; a bordered 2-manifold or open curves) and, if not, what is wrong.
#include <fmt/format.h>

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt {
namespace {

std::string plural(std::size_t count, const char* one, const char* many) {
  return fmt::format("{} {}", count, count == 1 ? one : many);
}

std::string join(const std::vector<std::string>& parts, const char* separator = ", ") {
  std::string line;
  for (const auto& part : parts) line += (line.empty() ? "" : separator) + part;
  return line;
}

}  // namespace

Verdict verdict(const Statistics& s) {
  const bool surface = s.dimension == 3;
  const bool bordered = s.kind == Surface_kind::bordered;
  std::vector<std::string> defects;
  if (s.facets == 0) defects.push_back(surface ? "no triangles" : "no edges");
  if (s.non_manifold_ridges > 0) {
    defects.push_back(surface
                          ? plural(s.non_manifold_ridges, "non-manifold edge", "non-manifold edges")
                          : plural(s.non_manifold_ridges, "branching sample", "branching samples"));
  }
  if (surface && s.non_manifold_vertices > 0) {
    defects.push_back(
        plural(s.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices"));
  }
  if (!bordered && s.boundary_ridges > 0) {
    defects.push_back(surface ? fmt::format("{} ({} border edges)",
                                            plural(s.boundary_loops, "hole", "holes"),
                                            s.boundary_ridges)
                              : plural(s.boundary_ridges, "curve end", "curve ends"));
  }
  if (s.unused_samples > 0) {
    defects.push_back(s.surface_vertices > 0
                          ? plural(s.unused_samples, "vertex", "vertices") + " on no face"
                          : plural(s.unused_samples, "sample", "samples") + " not on it");
  }

  std::string shape =
      surface ? fmt::format("{}, Euler characteristic {}",
                            plural(s.components, "component", "components"), s.euler_characteristic)
              : plural(s.components, "component", "components");
  const char* wanted = surface ? (bordered ? "bordered 2-manifold" : "closed 2-manifold")
                               : (bordered ? "set of curves" : "closed curve");
  const char* found_curves = s.components > 1 ? "closed curves" : "closed curve";
  Verdict v;
  v.manifold = defects.empty();
  if (v.manifold) {
    std::string what = surface || bordered ? wanted : found_curves;
    // The genus of a closed surface: of its one piece, or summed over its pieces.
    const long twice_genus = 2 * static_cast<long>(s.components) - s.euler_characteristic;
    if (surface && !bordered && s.components > 0 && twice_genus >= 0 && twice_genus % 2 == 0) {
      what +=
          fmt::format(s.components == 1 ? " of genus {}" : " of genus {} in all", twice_genus / 2);
    }
    if (bordered) {
      what +=
          fmt::format(" with {}", surface ? plural(s.boundary_loops, "border loop", "border loops")
                                          : plural(s.boundary_loops, "open curve", "open curves"));
    }
    // A result that does not interpolate passes near the samples, not through them.
    v.line = s.surface_vertices > 0
                 ? fmt::format("{}: {}, {} vertices of its own for {} samples", what, shape,
                               s.surface_vertices, s.samples)
                 : fmt::format("{}: {}, all {} samples on it", what, shape, s.samples);
  } else {
    // A bordered surface that is not a manifold still has its border loops to tell.
    if (surface && bordered) {
      shape = plural(s.boundary_loops, "border loop", "border loops") + ", " + shape;
    }
    v.line = fmt::format("NOT a {}: {}; {}", wanted, join(defects), shape);
  }
  // Handles the samples cannot vouch for (core/thin_handles.hpp): the genus may be wrong.
  if (s.thin_handles > 0) {
    v.line += fmt::format(
        "; {} suspect: a neck of 3-4 samples, thinner than their spacing (a gap or a "
        "touching the sampling cannot tell apart)",
        plural(s.thin_handles, "handle", "handles"));
  }
  // Handles the robust carving refused (methods/robust/solid_openings.hpp): the surface spans
  // a web there, however wide, which only a tunnel one sample wide would have opened; the genus
  // is the lower one.
  if (s.refused_handles > 0) {
    v.line += fmt::format(
        "; {} refused: a web kept where only a tunnel one sample wide would open it (a hole "
        "or a touching the sampling cannot tell apart; the genus may be higher)",
        plural(s.refused_handles, "handle", "handles"));
  }
  // What the surface passes through, and how far its topology can be trusted on noisy samples.
  if (s.cleaned) {
    std::vector<std::string> done;
    if (s.outliers_sought) {
      done.push_back(s.outliers_removed == 0
                         ? std::string("no outlier found")
                         : fmt::format("{} removed, not on it",
                                       plural(s.outliers_removed, "outlier", "outliers")));
    }
    if (s.smoothed) {
      // The noise after smoothing is not measured where too few samples can be (-1).
      const std::string before = s.noise >= 0
                                     ? fmt::format("noise {:.2f} of their spacing", s.noise)
                                     : std::string("noise not measured");
      const std::string after = s.noise_after >= 0 ? fmt::format("{:.2f} after", s.noise_after)
                                                   : std::string("not measured after");
      done.push_back(fmt::format("smoothed: {}, {}; moved {:.2f} of the spacing on average", before,
                                 after, s.cleaning_shift));
    }
    v.line += fmt::format("; through the samples cleaned first ({})", join(done, "; "));
  } else if (surface && s.noise >= noise_worth_cleaning) {
    v.line += fmt::format(
        "; the samples are noisy ({:.2f} of their spacing): expect a crumpled surface with "
        "invented handles (cleaning outliers+jet cleans them first)",
        s.noise);
  }
  return v;
}

}  // namespace sculpt
