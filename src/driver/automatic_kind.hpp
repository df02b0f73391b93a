// SPDX-License-Identifier: GPL-3.0-or-later
// One mode for real scans: closed or bordered, chosen from the samples.
//
// A user should not have to know whether a scan is closed. The closed reconstruction is right on
// closed shapes, and on a shape with openings it caps them with facets far wider than the
// samples' spacing (spanning_openings.hpp). So:
//
//   R_closed <- the closed reconstruction
//   if too few facets of R_closed span an opening to cap one (2 on a surface, 1 on a curve) and
//   R_closed has a surface: keep R_closed
//   R_bordered <- the bordered reconstruction
//   keep R_bordered if R_closed has no surface and R_bordered has one (a flat sheet of samples:
//   the closed result has no solid to bound, the bordered one is the sheet)
//   keep R_bordered if it has an opening (a border loop not torn by noise, through as many
//   samples as the rim of the smallest opening the test finds: 19), R_closed has at
//   least 2 facets spanning an opening per opening (1 on a curve),
//   defects(R_bordered) < defects(R_closed) + those facets, and
//   defects(R_bordered) <= defects(R_closed) + the loops noise tore in R_bordered; else R_closed
//   (a surface R_bordered with defects counts each piece and each handle more than R_closed has
//   as one more)
//
// defects = non-manifold ridges + non-manifold vertices + samples left off. A facet spanning an
// opening counts as a defect of the closed result: a surface made up across missing data. A
// closed shape whose sampling clumps or has a gap (a few spanning facets) keeps its closed
// result unless the bordered one is cleaner; a sheet, a part scanned from one side, a shell
// with holes has hundreds, and a bordered result with few defects.
//
// The last condition keeps a result from being traded for one with more defects:
// a CAD mesh's flat faces hold few vertices, so big facets there look like caps over openings,
// and the bordered rule cuts holes into them with pinched vertices and samples left off around
// (CGAL's couplingdown: closed, genus 9 as the mesh, against 15 loops, 17 non-manifold vertices
// and 2 samples off; anchor likewise; man and oblong, whose closed results leave 18 and 1
// samples off, had 64 and 26 defects bordered). Noise is allowed its due: a hole it tears
// can leave a pinch beside it, one defect per torn loop (a cap with noise of 5% of its spacing:
// 3 loops, 1 torn, 1 non-manifold vertex, stays bordered).
//
// Only the robust method chooses (chooses_kind): the paper's method, as published, is told its
// kind and takes automatic as closed, as do the methods without a bordered rule.
//
// Each attempt is a reconstruction of its own, but for stages 1-2, which the bordered attempt takes
// over from the closed one (first_stages.hpp): the one not kept shows as a stage of its own
// ("closed attempt" first, or "bordered attempt" last), the test for openings as "kind choice". The
// overall progress gives each run half the bar (which is not known
// in advance): a closed result kept jumps from one half to the end.
#pragma once

#include <algorithm>
#include <chrono>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../core/exact_normalisation.hpp"
#include "../core/first_stages.hpp"
#include "../core/spanning_openings.hpp"

namespace sculpt {

// The fewest facets over openings a closed result caps one opening with: a curve's gap is
// bridged by one edge; a surface's opening takes a cap of triangles (an opening the test can find
// is over ρ = 3 spacings in radius, with a rim of some 19 samples or more).
template <int D>
inline constexpr std::size_t facets_capping_an_opening = D == 2 ? 1 : 2;

// Whether `spanning` facets over openings are enough to have capped one. If not, keeps_bordered
// cannot keep a bordered result (it needs an opening capped by that many), so none is made,
// unless the closed result has no surface at all.
template <int D>
bool caps_an_opening(std::size_t spanning) {
  return spanning >= facets_capping_an_opening<D>;
}

inline std::size_t defects(const Statistics& stats) {
  return stats.non_manifold_ridges + stats.non_manifold_vertices + stats.unused_samples;
}

// The handles a surface (3D) has for certain: on a 2-manifold its genus summed over its pieces,
// from V - E + F = 2c - 2g - b (a border loop is a hole, not a handle). A pinched vertex where two
// fans meet reads up to one handle too many (on a border: one vertex and one loop fewer than
// its fans apart have), so each is taken off.
inline std::size_t certain_handles(const Statistics& stats) {
  const long twice = 2 * static_cast<long>(stats.components) - stats.euler_characteristic -
                     static_cast<long>(stats.boundary_loops) -
                     2 * static_cast<long>(stats.non_manifold_vertices);
  return twice > 0 ? static_cast<std::size_t>(twice / 2) : 0;
}

// Whether the bordered result is kept over the closed one, `spanning` facets of which span an
// opening. The bordered result's openings are its border loops but those torn in the sheet
// (Statistics::torn_loops: noise tears small holes the mending cannot close) and those through
// fewer samples than the rim of the smallest opening the spanning test can find
// (Statistics::short_loops, smallest_opening_rim: a hole of ρ = 3 spacings in radius has 19
// around): the closed result cannot have capped a shorter loop with facets over an opening,
// whatever caps it counted elsewhere. Without an opening, the closed result is the shape (a torus
// with noise of 5% of its spacing: 3 loops, all torn; CGAL's double-torus-example scanned, 35,000
// samples with noise of 0.5% of its diagonal, smoothed: bordered, 5 loops through 7 to 16 samples,
// 4 torn, and 4 pinched vertices, against a closed result of its genus). Nor is a loop an opening
// unless the closed result capped one there: with fewer facets over openings than it takes to cap
// the loops, they are holes the bordered rule made. The count is global: a real opening capped by
// fewer facets than it takes to cap all the bordered result's openings is lost. Nor is a result
// traded for one with more defects than the torn loops explain (see the top). A bordered surface
// with defects in more pieces than the closed one counts each piece more as a defect: a shape torn
// apart (CGAL's camel: 5 pieces, 11 pinched vertices and 14 torn loops, against a closed result of
// its genus through every sample, whose webs between the legs (refused handles,
// methods/robust/solid_openings.hpp) span 236 facets). Not a clean one, nor curves: separate sheets
// or strokes that the closed attempt joined are pieces of their own. A bordered surface with
// defects counts each handle more than the closed one's as a defect too: the closed result's
// handles are decided by evidence (methods/robust/solid_openings.hpp), the bordered rule's are not
// (a scan of CGAL's spool, noise 0.5% of the diagonal: bordered with 25 loops, 18 pinched vertices
// and 30 handles at least; closed, of genus 0 as the part).
template <int D>
bool keeps_bordered(const Statistics& closed, std::size_t spanning, const Statistics& bordered) {
  const std::size_t not_openings = bordered.torn_loops + bordered.short_loops;
  const std::size_t openings =
      bordered.boundary_loops - std::min(not_openings, bordered.boundary_loops);
  const std::size_t fallen_apart =
      D == 3 && defects(bordered) > 0 && bordered.components > closed.components
          ? bordered.components - closed.components
          : 0;
  const std::size_t more_handles =
      D == 3 && defects(bordered) > 0 && certain_handles(bordered) > certain_handles(closed)
          ? certain_handles(bordered) - certain_handles(closed)
          : 0;
  const std::size_t bordered_defects = defects(bordered) + fallen_apart + more_handles;
  return openings > 0 && openings * facets_capping_an_opening<D> <= spanning &&
         bordered_defects < defects(closed) + spanning &&
         bordered_defects <= defects(closed) + bordered.torn_loops;
}

// run(options, keep, given) reconstructs with the given options (kind closed or bordered),
// leaving its first stages in `keep` and starting from `given` (first_stages.hpp) where not null.
template <int D, class Run>
Reconstruction<D> reconstruct_choosing_kind(const Options& options, Run&& run) {
  if (options.kind != Surface_kind::automatic) return run(options, nullptr, nullptr);
  // The options of one run, its overall progress mapped onto [from, to] of the caller's.
  const auto run_options = [&](Surface_kind kind, double from, double to) {
    Options resolved = options;
    resolved.kind = kind;
    if (options.progress) {
      resolved.progress = [from, to, report = options.progress](const Progress& p) {
        Progress mapped = p;
        mapped.overall = from + (to - from) * p.overall;
        return report(mapped);
      };
    }
    return resolved;
  };
  const auto report = [&](double fraction, double overall) {
    if (options.progress && !options.progress(Progress{"kind choice", fraction, overall})) {
      throw Cancelled();
    }
  };
  if (!chooses_kind(options.method)) {
    return run(run_options(Surface_kind::closed, 0.0, 1.0), nullptr, nullptr);
  }
  const Options closed = run_options(Surface_kind::closed, 0.0, 0.5);
  const auto started = std::chrono::steady_clock::now();
  // Stages 1-2 of the closed attempt, for the bordered one (kept only if it can use them).
  Normalised_poles<D> closed_poles;
  const bool hands_on = starts_from_first_stages(run_options(Surface_kind::bordered, 0, 1), D);
  Reconstruction<D> closed_result = run(closed, hands_on ? &closed_poles : nullptr, nullptr);
  closed_result.stats.kind_chosen_automatically = true;

  report(0.0, 0.5);
  const auto choosing = std::chrono::steady_clock::now();
  // Measured where the stages were computed (the statistics record that exact translation and
  // scaling by a power of two): squared distances neither overflow nor underflow at any scale.
  const auto& sites = closed_result.sites;
  Normalisation<D> stages_normalisation;
  for (int k = 0; k < D; ++k) stages_normalisation.offset[k] = closed_result.stats.translation[k];
  stages_normalisation.exponent = closed_result.stats.scale_exponent;
  const std::vector<Point<D>> samples = normalised<D>(
      {sites.begin(), sites.begin() + closed_result.sample_count()}, stages_normalisation);
  const std::size_t spanning = count_spanning<D>(samples, closed_result.surface);
  closed_result.stats.closed_spanning_facets = spanning;
  const auto now = std::chrono::steady_clock::now();
  const double choice_seconds = std::chrono::duration<double>(now - choosing).count();
  const double closed_seconds = std::chrono::duration<double>(now - started).count();
  // A closed result without a surface (samples all but on one plane: no solid between them)
  // reconstructs nothing: the bordered attempt is made, and kept if it has one.
  const bool closed_is_empty = closed_result.surface.empty();
  const bool closed_stands = !caps_an_opening<D>(spanning) && !closed_is_empty;
  report(1.0, closed_stands ? 1.0 : 0.5);
  const auto add_choice_stage = [&] {
    auto& stats = closed_result.stats;
    const double peak = stats.stages.empty() ? 0.0 : stats.stages.back().peak_memory_mib;
    stats.stages.push_back(Stage_measure{"kind choice", choice_seconds, peak});
    stats.total_seconds += choice_seconds;
  };
  if (closed_stands) {
    add_choice_stage();
    return closed_result;
  }

  const auto bordered_started = std::chrono::steady_clock::now();
  std::optional<First_stages<D>> first_stages;
  if (hands_on) first_stages = first_stages_of(closed_result, std::move(closed_poles));
  Reconstruction<D> bordered_result = run(run_options(Surface_kind::bordered, 0.5, 1.0), nullptr,
                                          first_stages ? &*first_stages : nullptr);
  first_stages.reset();
  const bool bordered_replaces_nothing = closed_is_empty && !bordered_result.surface.empty();
  if (!bordered_replaces_nothing &&
      !keeps_bordered<D>(closed_result.stats, spanning, bordered_result.stats)) {
    // Closed kept: the attempt's time shows as a stage of its own.
    const double attempt_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - bordered_started).count();
    add_choice_stage();
    auto& stats = closed_result.stats;
    stats.stages.push_back(Stage_measure{"bordered attempt", attempt_seconds,
                                         bordered_result.stats.stages.back().peak_memory_mib});
    stats.total_seconds += attempt_seconds;
    return closed_result;
  }
  bordered_result.stats.kind_chosen_automatically = true;
  bordered_result.stats.closed_spanning_facets = spanning;
  auto& stages = bordered_result.stats.stages;
  stages.insert(stages.begin(),
                Stage_measure{"closed attempt", closed_seconds,
                              closed_result.stats.stages.empty()
                                  ? 0.0
                                  : closed_result.stats.stages.back().peak_memory_mib});
  bordered_result.stats.total_seconds += closed_seconds;
  return bordered_result;
}

}  // namespace sculpt
