// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0, before any method: the samples' noise measured (core/sample_noise.hpp) and, where
// Options::cleaning asks or the noise would crumple the robust method's surface, the samples
// cleaned: outliers removed (core/outlying_samples.hpp), then the rest smoothed
// (core/jet_smoothing.hpp). Interpolation then interpolates the cleaned samples: the statistics
// and the verdict say so, and the samples as given stay in the result to be drawn.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../core/jet_smoothing.hpp"
#include "../core/outlying_samples.hpp"
#include "../core/sample_noise.hpp"
#include "../core/stage_clock.hpp"
#include "../core/without.hpp"

namespace sculpt {

// The nearest samples a jet is fitted to: CGAL's examples' choice, some four rings of neighbours
// on a surface, enough for a quadric's six coefficients to average the noise out.
inline constexpr unsigned jet_neighbours = 24;
// Jet smoothing repeats until the noise measures this share of noise_worth_cleaning, at most
// this many passes (see reconstruct_cleaned).
inline constexpr double quiet_after_cleaning = 0.1;
inline constexpr int jet_passes_at_most = 4;

// What the cleaning does: asked for, or (automatic) both where the robust method reconstructs a
// surface from samples whose noise would crumple it. The outliers of noisy samples go with the
// noise; those of clean samples are removed only when asked (a mesh's lone vertices, far from
// denser ones, look like outliers: core/outlying_samples.hpp). Throws Input_error where a
// cleaning is asked for curves' samples.
struct Cleaning_plan {
  bool removes_outliers = false;
  bool smooths = false;
  bool any() const { return removes_outliers || smooths; }
};

inline Cleaning_plan cleaning_plan(const Options& options, int dimension, double noise) {
  switch (options.cleaning) {
    case Cleaning::none:
      return {};
    case Cleaning::automatic: {
      const bool noisy =
          options.method == Method::robust && dimension == 3 && noise >= noise_worth_cleaning;
      return {noisy, noisy};
    }
    case Cleaning::jet:
    case Cleaning::outliers:
    case Cleaning::outliers_and_jet:
      break;
  }
  if (dimension != 3) {
    throw Input_error(std::string("cleaning (") + to_string(options.cleaning) +
                      ") cleans surfaces' samples (3D points), not curves'");
  }
  return {options.cleaning != Cleaning::jet, options.cleaning != Cleaning::outliers};
}

// The noise as given on the result, and the stages' measures: measuring the noise is one of
// the checks of the input, the cleaning a stage of its own, the first (it is not planned: the
// automatic choice is made here, after the progress is planned).
template <int D>
Reconstruction<D> with_noise_measured(Reconstruction<D> result, double noise, double noise_seconds,
                                      const std::optional<Stage_measure>& cleaning) {
  result.stats.noise = noise;
  auto& stages = result.stats.stages;
  const auto checks = std::find_if(stages.begin(), stages.end(),
                                   [](const Stage_measure& s) { return s.name == "checks"; });
  if (checks != stages.end()) checks->seconds += noise_seconds;
  if (cleaning) stages.insert(stages.begin(), *cleaning);
  result.stats.total_seconds += noise_seconds + (cleaning ? cleaning->seconds : 0);
  return result;
}

// `check(samples)` refuses samples no method can take (core/input_checks.hpp, repeated points
// too): the cleaning runs on checked samples, and a refusal names the points as given.
// `reconstruct(samples, options)` runs the method (and the kind's choice) on the samples given.
template <int D, class Check, class Reconstruct>
Reconstruction<D> reconstruct_cleaned(const std::vector<Point<D>>& samples, const Options& options,
                                      Check&& check, Reconstruct&& reconstruct) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  auto start = Clock::now();
  const Noise_measure given = measure_noise<D>(samples);
  const double noise_seconds = seconds_since(start);
  const Cleaning_plan plan = cleaning_plan(options, D, given.noise);
  if (!plan.any()) {
    Reconstruction<D> result = reconstruct(samples, options);
    return with_noise_measured(std::move(result), given.noise, noise_seconds, std::nullopt);
  }
  check(samples);
  if (samples.size() < 100) {  // the automatic cleaning never runs on so few: not measured
    throw Input_error(std::string("cleaning (") + to_string(options.cleaning) +
                      ") judges each sample by its nearest (" +
                      (plan.smooths ? std::to_string(jet_neighbours) + " for the smoothing"
                                    : std::to_string(outlier_neighbours)) +
                      "): it needs at least 100 samples, not " + std::to_string(samples.size()));
  }
  start = Clock::now();
  std::vector<int> removed;
  if constexpr (D == 3) {
    if (plan.removes_outliers) removed = outlying_samples(samples);
  }
  const std::vector<Point<D>> kept = without(samples, removed);
  std::vector<Point<D>> cleaned = kept;
  // The smoothing measures its own; removing outliers alone is measured here.
  Noise_measure after = plan.smooths ? given : measure_noise<D>(kept);
  // One pass of jet smoothing leaves about a tenth of the noise, but gathered into bumps a few
  // samples wide, which the measure reads low and a surface through the samples still
  // crumples over: CGAL's fandisk, anchor and joint sampled 35,000 times with noise of 0.5% of
  // the diagonal came back of genus 15, 25 and 5 after one pass, and of their own (0, 4, 2)
  // after two or three. So the passes repeat until the measure reads a tenth of the noise
  // that asks for cleaning, at most four.
  for (int pass = 0; plan.smooths && pass < jet_passes_at_most &&
                     (pass == 0 || after.noise >= quiet_after_cleaning * noise_worth_cleaning);
       ++pass) {
    if constexpr (D == 3) cleaned = jet_smoothed(cleaned, jet_neighbours);
    const bool finite = std::all_of(cleaned.begin(), cleaned.end(), [](const Point<D>& p) {
      return std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); });
    });
    if (!finite) {
      throw Input_error(
          "cleaning (jet smoothing) failed on these samples: a neighbourhood is degenerate "
          "(collinear or repeated samples); reconstruct them without it (cleaning none)");
    }
    after = measure_noise<D>(cleaned);
  }
  double moved = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += (cleaned[i][k] - kept[i][k]) * (cleaned[i][k] - kept[i][k]);
    moved += std::sqrt(d2) / static_cast<double>(kept.size());
  }
  const Stage_measure cleaning{"cleaning", seconds_since(start), peak_memory_mib()};
  Reconstruction<D> result = reconstruct(cleaned, options);
  result.stats.cleaned = true;
  result.stats.smoothed = plan.smooths;
  result.stats.outliers_sought = plan.removes_outliers;
  result.stats.outliers_removed = removed.size();
  result.stats.noise_after = after.noise;
  result.stats.cleaning_shift = given.spacing > 0 ? moved / given.spacing : 0;
  // Which given sample each kept one is, for the writers (normals and colours go with them).
  result.removed_outliers = std::move(removed);
  if (options.keep_triangulations) result.given_samples = samples;  // the viewer draws them
  return with_noise_measured(std::move(result), given.noise, noise_seconds, cleaning);
}

}  // namespace sculpt
