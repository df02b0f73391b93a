// SPDX-License-Identifier: GPL-3.0-or-later
#include "progress_display.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace sculpt::cli {
namespace {

bool status_shown = false;

void show_status(const std::string& text) {
  std::cerr << '\r' << text << "\033[K" << std::flush;
  status_shown = true;
}

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

std::string time_left_text(double elapsed, double overall) {
  // The stages are weighted by their usual share of the time (core's Progress::overall), so
  // the rate so far predicts the rest; too early, it predicts nothing.
  if (!(overall >= 0.03) || overall >= 1 || elapsed < 1) return "";
  const double left = elapsed * (1 - overall) / overall;
  if (left < 60) return fmt::format("about {:.0f} s left", std::max(1.0, std::round(left)));
  return fmt::format("about {:.0f} min left", std::round(left / 60));
}

std::function<bool(const Progress&)> progress_display(std::size_t samples, bool quiet) {
  if (quiet || samples < 20000) return {};
  const Clock::time_point start = Clock::now();
  if (isatty(STDERR_FILENO)) {
    return [start, last = std::string(), shown = std::string()](const Progress& progress) mutable {
      if (!progress.stage) return true;
      const std::string left =
          time_left_text(seconds_between(start, Clock::now()), progress.overall);
      const std::string text =
          fmt::format("sculpt: {}% ({}){}", static_cast<int>(100 * progress.overall),
                      progress.stage, left.empty() ? "" : ", " + left);
      if (text != shown) show_status(text);  // only when it changes: a terminal is slow
      shown = text;
      return true;
    };
  }
  // A log: one line per stage, when it ends.
  return [start, stage_start = start](const Progress& progress) mutable {
    if (!progress.stage) return true;
    const Clock::time_point now = Clock::now();
    if (progress.fraction == 0) stage_start = now;
    if (progress.fraction < 1) return true;
    const std::string left = time_left_text(seconds_between(start, now), progress.overall);
    std::cerr << fmt::format(
        "sculpt: {} done in {:.2f} s ({}%{})\n", progress.stage, seconds_between(stage_start, now),
        static_cast<int>(100 * progress.overall), left.empty() ? "" : ", " + left);
    return true;
  };
}

void clear_progress_display() {
  if (status_shown) std::cerr << "\r\033[K" << std::flush;
  status_shown = false;
}

}  // namespace sculpt::cli
