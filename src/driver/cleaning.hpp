// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 0, before any method: the samples' noise measured (core/sample_noise.hpp) and, where
// Options::cleaning asks or the noise would crumple the robust method's surface, the samples
// smoothed (core/jet_smoothing.hpp). Interpolation then interpolates the smoothed samples: the
// statistics and the verdict say so, and the samples as given stay in the result to be drawn.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <vector>

#include "../core/jet_smoothing.hpp"
#include "../core/sample_noise.hpp"
#include "../core/stage_clock.hpp"

namespace sculpt {

// The nearest samples a jet is fitted to: CGAL's examples' choice, some four rings of neighbours
// on a surface, enough for a quadric's six coefficients to average the noise out.
inline constexpr unsigned jet_neighbours = 24;
// Jet smoothing repeats until the noise measures this share of noise_worth_cleaning, at most
// this many passes (see reconstruct_cleaned).
inline constexpr double quiet_after_cleaning = 0.1;
inline constexpr int jet_passes_at_most = 4;

// Whether the samples are smoothed: asked for, or (automatic) the robust method on a surface
// whose noise would crumple it. Throws Input_error where smoothing is asked and cannot be done.
inline bool smooths(const Options& options, int dimension, std::size_t samples, double noise) {
  if (options.cleaning == Cleaning::jet) {
    if (dimension != 3) {
      throw Input_error(
          "cleaning (jet smoothing) smooths surfaces' samples (3D points), not curves'");
    }
    return samples >= 100;  // fewer are refused below
  }
  return options.cleaning == Cleaning::automatic && options.method == Method::robust &&
         dimension == 3 && noise >= noise_worth_cleaning;
}

// `reconstruct(samples, options)` runs the method (and the kind's choice) on the samples given.
template <int D, class Reconstruct>
Reconstruction<D> reconstruct_cleaned(const std::vector<Point<D>>& samples, const Options& options,
                                      Reconstruct&& reconstruct) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  auto start = Clock::now();
  const Noise_measure given = measure_noise<D>(samples);
  const double noise_seconds = seconds_since(start);
  if (options.cleaning == Cleaning::jet && samples.size() < 100) {
    throw Input_error("cleaning (jet smoothing) fits each sample's " +
                      std::to_string(jet_neighbours) +
                      " nearest: it needs at least 100 samples, "
                      "not " +
                      std::to_string(samples.size()));
  }
  // Coordinates that are not numbers are the input's to refuse (the input checks name them),
  // before any smoothing; a smoothing that made some of its own is refused as such.
  const auto finite = [](const std::vector<Point<D>>& points) {
    return std::all_of(points.begin(), points.end(), [](const Point<D>& p) {
      return std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); });
    });
  };
  Reconstruction<D> result;
  std::optional<Stage_measure> cleaning;
  if (!smooths(options, D, samples.size(), given.noise) || !finite(samples)) {
    result = reconstruct(samples, options);
  } else {
    start = Clock::now();
    // One pass of jet smoothing leaves about a tenth of the noise, but gathered into bumps a few
    // samples wide, which the measure reads low and a surface through the samples still
    // crumples over: CGAL's fandisk, anchor and joint sampled 35,000 times with noise of 0.5% of
    // the diagonal came back of genus 15, 25 and 5 after one pass, and of their own (0, 4, 2)
    // after two or three. So the passes repeat until the measure reads a tenth of the noise
    // that asks for cleaning, at most four.
    std::vector<Point<D>> smoothed = samples;
    Noise_measure after = given;
    for (int pass = 0; pass < jet_passes_at_most &&
                       (pass == 0 || after.noise >= quiet_after_cleaning * noise_worth_cleaning);
         ++pass) {
      if constexpr (D == 3) smoothed = jet_smoothed(smoothed, jet_neighbours);
      if (!finite(smoothed)) {
        throw Input_error(
            "cleaning (jet smoothing) failed on these samples: a neighbourhood is degenerate "
            "(collinear or repeated samples); reconstruct them without it (cleaning none)");
      }
      after = measure_noise<D>(smoothed);
    }
    double moved = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      double d2 = 0;
      for (int k = 0; k < D; ++k)
        d2 += (smoothed[i][k] - samples[i][k]) * (smoothed[i][k] - samples[i][k]);
      moved += std::sqrt(d2) / static_cast<double>(samples.size());
    }
    cleaning = Stage_measure{"cleaning", seconds_since(start), peak_memory_mib()};
    result = reconstruct(smoothed, options);
    result.stats.cleaned = true;
    result.stats.noise_after = after.noise;
    result.stats.cleaning_shift = given.spacing > 0 ? moved / given.spacing : 0;
    if (options.keep_triangulations) result.given_samples = samples;  // the viewer draws them
  }
  result.stats.noise = given.noise;
  // Measuring the noise is one of the checks of the input; the cleaning a stage of its own, the
  // first (it is not planned: the automatic choice is made here, after the progress is planned).
  auto& stages = result.stats.stages;
  const auto checks = std::find_if(stages.begin(), stages.end(),
                                   [](const Stage_measure& s) { return s.name == "checks"; });
  if (checks != stages.end()) checks->seconds += noise_seconds;
  if (cleaning) stages.insert(stages.begin(), *cleaning);
  result.stats.total_seconds += noise_seconds + (cleaning ? cleaning->seconds : 0);
  return result;
}

}  // namespace sculpt
