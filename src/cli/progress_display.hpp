// SPDX-License-Identifier: GPL-3.0-or-later
// How a long reconstruction reports its progress on stderr, for a person or for a log:
//   on a terminal, one line rewritten in place: the share done, the stage, the time left;
//   in a log (stderr is a file or a pipe: CI, batch jobs, nohup), a plain line as each stage
//   ends, with its time, the share done and the time left;
//   nothing with -q, or for a run too short to wonder about (under 20,000 samples).
// A failure is still one line: the terminal's status line is erased before anything else.
#pragma once

#include <functional>
#include <sculpt/sculpt.hpp>
#include <string>

namespace sculpt::cli {

// "about 40 s left", "about 3 min left"; empty until an estimate means something (a few
// percent done, a second gone).
std::string time_left_text(double elapsed_seconds, double overall_fraction);

// The progress callback for a run of `samples` points (an empty function: no display).
std::function<bool(const Progress&)> progress_display(std::size_t samples, bool quiet);

// Erases the terminal's status line, if one is shown.
void clear_progress_display();

}  // namespace sculpt::cli
