// Times each stage of a reconstruction, records the process's peak memory after it, and gives
// the caller's progress callback a chance to cancel between stages.
#pragma once

#include <sys/resource.h>

#include <chrono>
#include <sculpt/sculpt.hpp>

namespace sculpt {

inline double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

class Stage_clock {
 public:
  Stage_clock(Statistics& stats, const Options& options) : stats_(stats), options_(options) {}

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
    if (options_.progress && !options_.progress(Progress{stage, fraction})) throw Cancelled();
  }
  void report(double fraction) const { report(name_, fraction); }

 private:
  using Clock = std::chrono::steady_clock;
  Statistics& stats_;
  const Options& options_;
  const char* name_ = nullptr;
  Clock::time_point started_;
};

}  // namespace sculpt
