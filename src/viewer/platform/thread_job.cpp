// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop's reconstruction job: a thread of its own; a cancel takes effect at the next
// progress report, and a new job waits for the cancelled one to end.
#include <atomic>
#include <mutex>
#include <thread>

#include "viewer/reconstruction_job.hpp"

namespace sculpt::viewer {

namespace {

class Thread_job : public Reconstruction_job {
 public:
  ~Thread_job() override { cancel_and_join(); }

  void start(Job_request request) override {
    cancel_and_join();
    cancelled_ = abandoned_ = false;
    running_ = true;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      status_ = {"reading", 0};
      outcome_.reset();
    }
    thread_ = std::thread(&Thread_job::run, this, std::move(request));
  }
  void request_cancel() override { cancelled_ = true; }
  void abandon() override {
    abandoned_ = true;
    cancelled_ = true;
  }
  bool running() const override { return running_; }
  bool outcome_waiting() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    return !running_ && outcome_.has_value() && !abandoned_;
  }
  Status status() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
  }
  std::optional<Outcome> take_outcome() override {
    if (running_) return std::nullopt;
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<Outcome> outcome;
    outcome.swap(outcome_);
    if (abandoned_) return std::nullopt;
    return outcome;
  }

 private:
  void cancel_and_join() {
    cancelled_ = true;
    if (thread_.joinable()) thread_.join();
  }

  void run(Job_request request) {
    Outcome outcome = frontend::run_request(std::move(request), [this](const Progress& progress) {
      std::lock_guard<std::mutex> lock(mutex_);
      status_ = {progress.stage ? progress.stage : "", progress.fraction, progress.overall};
      return !cancelled_;
    });
    {
      std::lock_guard<std::mutex> lock(mutex_);
      outcome_ = std::move(outcome);
    }
    running_ = false;
  }

  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> abandoned_{false};
  mutable std::mutex mutex_;
  Status status_;
  std::optional<Outcome> outcome_;
};

}  // namespace

std::unique_ptr<Reconstruction_job> make_reconstruction_job() {
  return std::make_unique<Thread_job>();
}

}  // namespace sculpt::viewer
