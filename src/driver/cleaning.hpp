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

// The samples but those listed (increasing), in their order.
template <int D>
std::vector<Point<D>> without(const std::vector<Point<D>>& samples, const std::vector<int>& gone) {
  std::vector<Point<D>> kept;
  kept.reserve(samples.size() - gone.size());
  auto next_gone = gone.begin();
  for (int i = 0; i < static_cast<int>(samples.size()); ++i) {
    if (next_gone != gone.end() && *next_gone == i) {
      ++next_gone;
    } else {
      kept.push_back(samples[i]);
    }
  }
  return kept;
}

// The outliers (core/outlying_samples.hpp), found again among the samples left until none is
// found, at most four times: two outliers side by side each count the other among their
// neighbours, and the second shows alone once the first is gone.
inline std::vector<int> outliers_removed_in_rounds(const std::vector<Point<3>>& samples) {
  std::vector<int> removed;
  std::vector<int> given_index(samples.size());  // of the samples left
  for (std::size_t i = 0; i < samples.size(); ++i) given_index[i] = static_cast<int>(i);
  std::vector<Point<3>> left = samples;
  for (int round = 0; round < 4; ++round) {
    const std::vector<int> found = outlying_samples(left);
    if (found.empty()) break;
    for (int i : found) removed.push_back(given_index[i]);
    left = without<3>(left, found);
    std::vector<int> still;
    still.reserve(left.size());
    auto next_found = found.begin();
    for (int i = 0; i < static_cast<int>(given_index.size()); ++i) {
      if (next_found != found.end() && *next_found == i) {
        ++next_found;
      } else {
        still.push_back(given_index[i]);
      }
    }
    given_index = std::move(still);
  }
  std::sort(removed.begin(), removed.end());
  return removed;
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
  const Cleaning_plan plan = cleaning_plan(options, D, given.noise);
  if (plan.any() && options.cleaning != Cleaning::automatic && samples.size() < 100) {
    throw Input_error(std::string("cleaning (") + to_string(options.cleaning) +
                      ") judges each sample by its nearest (" + std::to_string(jet_neighbours) +
                      " for the smoothing): it needs at least 100 samples, not " +
                      std::to_string(samples.size()));
  }
  // Coordinates that are not numbers are the input's to refuse (the input checks name them),
  // before any cleaning; a smoothing that made some of its own is refused as such.
  const auto finite = [](const std::vector<Point<D>>& points) {
    return std::all_of(points.begin(), points.end(), [](const Point<D>& p) {
      return std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); });
    });
  };
  Reconstruction<D> result;
  std::optional<Stage_measure> cleaning;
  if (!plan.any() || samples.size() < 100 || !finite(samples)) {
    result = reconstruct(samples, options);
  } else {
    start = Clock::now();
    std::vector<int> removed;
    if constexpr (D == 3) {
      if (plan.removes_outliers) removed = outliers_removed_in_rounds(samples);
    }
    const std::vector<Point<D>> kept = without<D>(samples, removed);
    std::vector<Point<D>> cleaned = kept;
    Noise_measure after = measure_noise<D>(kept);
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
      if (!finite(cleaned)) {
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
    cleaning = Stage_measure{"cleaning", seconds_since(start), peak_memory_mib()};
    result = reconstruct(cleaned, options);
    result.stats.cleaned = true;
    result.stats.smoothed = plan.smooths;
    result.stats.outliers_removed = removed.size();
    result.stats.noise_after = after.noise;
    result.stats.cleaning_shift = given.spacing > 0 ? moved / given.spacing : 0;
    if (options.keep_triangulations) {  // the viewer draws them
      result.given_samples = samples;
      result.removed_outliers = std::move(removed);
    }
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
