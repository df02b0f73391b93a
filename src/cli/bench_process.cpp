// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench_process.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <stdexcept>

namespace sculpt::cli {
namespace {

// The CPU seconds (user + system) a resource usage records.
double cpu_seconds(const rusage& usage) {
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace

double own_peak_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  }
  return 0;
}

nlohmann::json run_job_process(const std::vector<std::string>& arguments) {
  std::vector<std::string> words = {"sculpt", "bench-job"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  int channel[2];
  if (pipe(channel) != 0) throw std::runtime_error("pipe failed");
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child < 0) {
    close(channel[0]);
    close(channel[1]);
    throw std::runtime_error("fork failed");
  }
  if (child == 0) {
    dup2(channel[1], STDOUT_FILENO);
    close(channel[0]);
    close(channel[1]);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  close(channel[1]);
  std::string text;
  char buffer[65536];
  for (ssize_t got; (got = read(channel[0], buffer, sizeof buffer)) > 0;) text.append(buffer, got);
  close(channel[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) {
    return {{"error", "the measuring process died"}};
  }
  auto result = nlohmann::json::parse(text, nullptr, false);
  if (result.is_discarded()) return {{"error", "the measuring process wrote no JSON"}};
  // Less the time the job spent judging its result (Evaluation_time).
  const auto judging = result.value("evaluation", nlohmann::json::object());
  result["process"] = {
      {"cpu_seconds", cpu_seconds(usage) - judging.value("cpu_seconds", 0.0)},
      {"wall_seconds", wall - judging.value("wall_seconds", 0.0)},
      {"peak_mib", result.value("own_peak_mib", double(usage.ru_maxrss) / 1024.0)}};
  return result;
}

nlohmann::json median_run(std::vector<nlohmann::json> runs) {
  std::vector<nlohmann::json> good;
  for (auto& run : runs) {
    if (!run.contains("error")) good.push_back(std::move(run));
  }
  if (good.empty()) return runs.front();
  std::sort(good.begin(), good.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return double(a["process"]["cpu_seconds"]) < double(b["process"]["cpu_seconds"]);
  });
  return good[(good.size() - 1) / 2];
}

nlohmann::json median_of_runs(const std::vector<std::string>& arguments, int runs) {
  std::vector<nlohmann::json> measured;
  for (int run = 0; run < std::max(1, runs); ++run) measured.push_back(run_job_process(arguments));
  return median_run(std::move(measured));
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return cpu_seconds(usage);
}

}  // namespace sculpt::cli
