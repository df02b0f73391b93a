// SPDX-License-Identifier: GPL-3.0-or-later
// What `sculpt bench` measures of a process: each measurement runs in a process of its own
// (`sculpt bench-job`, started afresh), so its CPU time and peak memory are the whole process's,
// and of several runs the median one is kept.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sculpt::cli {

// The peak resident memory of this process's own image, in MiB (VmHWM). Unlike the rusage
// maximum, it does not carry over the memory of the parent that forked it (Linux keeps that high
// mark across exec): a job started by a large process reports its own peak.
double own_peak_mib();
// The CPU seconds (user + system) this process has used so far.
double process_cpu_seconds();
// Runs this executable as `sculpt bench-job ARGUMENTS...` and returns the JSON it prints, with
// the process's CPU time (user + system), wall time and peak resident memory.
nlohmann::json run_job_process(const std::vector<std::string>& arguments);
// Of several runs of one measurement, the one of median CPU time.
nlohmann::json median_run(std::vector<nlohmann::json> runs);
// One job measured `runs` times, each in a fresh process: the median run.
nlohmann::json median_of_runs(const std::vector<std::string>& arguments, int runs);

}  // namespace sculpt::cli
