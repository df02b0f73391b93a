// SPDX-License-Identifier: GPL-3.0-or-later
// The browser's reconstruction job: the request goes to a Web Worker running the core's
// WebAssembly module (src/web/core_module.cpp, through web/sculpt-page.js), which posts its
// progress and, at the end, the reconstruction with every stage as bytes (io/reconstruction_bytes
// .hpp). The page's own WebAssembly memory is not shared with the worker's: that would need a
// cross-origin-isolated page, which static hosts such as GitHub Pages cannot serve. A cancel ends
// the worker at once (the page starts another), so the UI never waits for a stage to report.
// Several jobs may run at once (side by side runs the compared methods beside the main one):
// each run has an id of its own across all jobs, and the page's messages go to the job that
// owns the id; the page gives each running job a worker of its own.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <map>

#include "io/reconstruction_bytes.hpp"
#include "viewer/reconstruction_job.hpp"

namespace sculpt::viewer {

namespace {

// JavaScript below, which clang-format would reshape.
// clang-format off
EM_JS(void, start_in_worker, (int id, const char* request, const char* path),
      { Module["sculptJobs"].start(id, UTF8ToString(request), UTF8ToString(path)); });

EM_JS(void, stop_worker, (int id), { Module["sculptJobs"].cancel(id); });
// clang-format on

class Worker_job;
// The jobs running, by the id of their run: the page's messages name it.
std::map<int, Worker_job*> running_jobs;
int last_id = 0;

Worker_job* job_of(int id) {
  const auto found = running_jobs.find(id);
  return found == running_jobs.end() ? nullptr : found->second;
}

class Worker_job : public Reconstruction_job {
 public:
  Worker_job() = default;
  ~Worker_job() override {
    if (running_) stop_worker(id_);
    running_jobs.erase(id_);
  }

  void start(Job_request request) override {
    if (running_) stop_worker(id_);
    running_jobs.erase(id_);
    id_ = ++last_id;
    running_jobs[id_] = this;
    running_ = true;
    abandoned_ = false;
    outcome_.reset();
    status_ = {"reading", 0, 0};
    const std::string json = frontend::to_json(request).dump();
    start_in_worker(id_, json.c_str(), request.path.c_str());
  }
  void request_cancel() override {
    if (running_) stop_worker(id_);  // the page answers with finished(id, "cancelled")
  }
  void abandon() override {
    abandoned_ = true;
    request_cancel();
  }
  bool running() const override { return running_; }
  bool outcome_waiting() const override { return !running_ && outcome_ && !abandoned_; }
  Status status() const override { return status_; }
  std::optional<Outcome> take_outcome() override {
    if (running_) return std::nullopt;
    std::optional<Outcome> outcome;
    outcome.swap(outcome_);
    if (abandoned_) return std::nullopt;
    return outcome;
  }

  // From the page: the worker's progress, and its end.
  void progress(int id, const char* stage, double fraction, double overall) {
    if (id == id_ && running_) status_ = {stage, fraction, overall};
  }
  void finished(int id, const char* error, const char* description, const std::uint8_t* bytes,
                std::size_t size) {
    if (id != id_ || !running_) return;
    Outcome outcome;
    outcome.error = error;
    outcome.description = description;
    if (outcome.error.empty()) {
      try {
        if (io::dimension_of_bytes(bytes, size) == 2) {
          outcome.reconstruction = io::reconstruction_from_bytes<2>(bytes, size);
        } else {
          outcome.reconstruction = io::reconstruction_from_bytes<3>(bytes, size);
        }
      } catch (const std::exception& e) {
        outcome.error = e.what();
      }
    }
    outcome_ = std::move(outcome);
    running_ = false;
    running_jobs.erase(id_);
  }

 private:
  int id_ = 0;
  bool running_ = false;
  bool abandoned_ = false;
  Status status_;
  std::optional<Outcome> outcome_;
};

}  // namespace

std::unique_ptr<Reconstruction_job> make_reconstruction_job() {
  return std::make_unique<Worker_job>();
}

}  // namespace sculpt::viewer

// Called by web/sculpt-page.js with the worker's messages.
extern "C" {

EMSCRIPTEN_KEEPALIVE void sculpt_job_progress(int id, const char* stage, double fraction,
                                              double overall) {
  if (auto* job = sculpt::viewer::job_of(id)) job->progress(id, stage, fraction, overall);
}

// Whether a reconstruction runs (the benchmark counts the frames drawn meanwhile).
EMSCRIPTEN_KEEPALIVE int sculpt_job_running() {
  return sculpt::viewer::running_jobs.empty() ? 0 : 1;
}

EMSCRIPTEN_KEEPALIVE void sculpt_job_finished(int id, const char* error, const char* description,
                                              const std::uint8_t* bytes, int size) {
  if (auto* job = sculpt::viewer::job_of(id))
    job->finished(id, error, description, bytes, std::size_t(size));
}

}  // extern "C"
