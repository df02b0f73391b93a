// SPDX-License-Identifier: GPL-3.0-or-later
// Times each stage of a reconstruction, records the process's peak memory after it, and gives
// the caller's progress callback a chance to cancel between stages.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

inline double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

// Each stage's usual share of a run's time, relative to the Delaunay triangulation's (measured
// on the built-in examples and CGAL's meshes): what the overall progress weighs stages by.
inline double usual_weight(const char* stage) {
  static const struct {
    const char* name;
    double weight;
  } weights[] = {{"checks", 0.02},         {"delaunay", 1.0},      {"poles", 0.3},
                 {"seeds", 0.01},          {"labelling", 0.3},     {"propagation", 0.3},
                 {"queries", 0.3},         {"insertion", 0.5},     {"carving", 0.5},
                 {"solid", 0.05},          {"surface", 0.05},      {"topology", 0.05},
                 {"voronoi", 0.3},         {"crust", 2.0},         {"filtering", 0.3},
                 {"pruning", 0.5},         {"walk", 0.5},          {"mending", 0.05},
                 {"cocone", 1.0},          {"undersampling", 0.2}, {"peeling", 0.5},
                 {"power diagram", 7.0},   {"power-crust", 2.5},   {"sculpting", 1.0},
                 {"advancing-front", 5.0}, {"alpha-shape", 5.0}};
  for (const auto& w : weights) {
    if (std::strcmp(w.name, stage) == 0) return w.weight;
  }
  return 0.3;
}

class Stage_clock {
 public:
  Stage_clock(Statistics& stats, const Options& options) : stats_(stats), options_(options) {}

  // The stages the run will start, in order: overall progress is measured across them.
  void plan(std::vector<const char*> stages) {
    plan_ = std::move(stages);
    total_weight_ = 0;
    for (const char* stage : plan_) total_weight_ += usual_weight(stage);
  }

  // Ends the running stage (if any; its progress reaches 1) and starts the next one.
  void start(const char* stage) {
    if (name_) report(name_, 1.0);
    stop();
    report(stage, 0.0);
    name_ = stage;
    started_ = Clock::now();
  }

  // Ends the last stage: its progress reaches 1.
  void finish() {
    if (name_) report(name_, 1.0);
    stop();
  }

  void stop() {
    if (!name_) return;
    const double seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    stats_.stages.push_back({name_, seconds, peak_memory_mib()});
    stats_.total_seconds += seconds;
    name_ = nullptr;
  }

  // Tells the caller how far the running stage is; throws Cancelled if it asks to stop.
  void report(const char* stage, double fraction) const {
    if (!options_.progress) return;
    if (!options_.progress(Progress{stage, fraction, overall(stage, fraction)})) throw Cancelled();
  }
  void report(double fraction) const { report(name_, fraction); }
  // For a loop of `total` steps: every `every` steps, reports how far step `done` is (at most 1:
  // a loop may take more steps than it expected).
  void report_every(std::size_t done, std::size_t total, std::size_t every) const {
    if (done % every == 0 && total > 0) report(std::min(1.0, double(done) / double(total)));
  }

 private:
  // The planned stages before this one and this one's fraction, by weight; a stage outside
  // the plan holds the progress where it was.
  double overall(const char* stage, double fraction) const {
    if (total_weight_ <= 0) return 0;
    double done = 0;
    for (const char* planned : plan_) {
      if (std::strcmp(planned, stage) == 0) {
        last_overall_ =
            std::max(last_overall_, (done + usual_weight(planned) * fraction) / total_weight_);
        break;
      }
      done += usual_weight(planned);
    }
    return std::min(1.0, last_overall_);
  }

  using Clock = std::chrono::steady_clock;
  std::vector<const char*> plan_;
  double total_weight_ = 0;
  mutable double last_overall_ = 0;
  Statistics& stats_;
  const Options& options_;
  const char* name_ = nullptr;
  Clock::time_point started_;
};

}  // namespace sculpt
