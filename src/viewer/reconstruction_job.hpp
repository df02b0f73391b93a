// Runs a reconstruction off the UI thread: loading the input and every stage, with the stage
// name and progress readable at any time and a cancel that takes effect at the next report.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <string>
#include <thread>
#include <variant>
#include <vector>

namespace sculpt::viewer {

using Any_reconstruction = std::variant<Reconstruction<2>, Reconstruction<3>>;

struct Job_request {
  std::string path, example;  // one of them, or edited points
  // Points edited in the viewer (2D), with what they were edited from and the edit count.
  std::shared_ptr<const std::vector<Point<2>>> edited_points;
  std::string edited_from;
  int edits = 0;
  int dimension = 0;              // 0: as the file says
  bool merge_duplicates = false;  // drop a file's repeated points instead of refusing them
  std::string shown_as;  // how to name the input when not by its path (e.g. "CGAL's fandisk.off")
  Options options;
};

class Reconstruction_job {
 public:
  ~Reconstruction_job();

  void start(Job_request request);  // cancels and replaces a running job
  // Asks the job to stop at its next progress report; returns at once (the UI stays live).
  void request_cancel() { cancelled_ = true; }
  // Cancels a running job and drops whatever it ends with: the viewer has moved on.
  void abandon() {
    abandoned_ = true;
    cancelled_ = true;
  }
  bool running() const { return running_; }
  // Ended, with an outcome nobody has taken yet.
  bool outcome_waiting() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return !running_ && outcome_.has_value() && !abandoned_;
  }

  struct Status {
    std::string stage;
    double fraction = 0;  // within the stage
    double overall = 0;   // across the whole reconstruction
  };
  Status status() const;

  // Once the job has ended: its reconstruction and input description, or its error message.
  struct Outcome {
    std::optional<Any_reconstruction> reconstruction;
    std::string description;
    std::string error;  // empty on success; "cancelled" when cancelled
  };
  std::optional<Outcome> take_outcome();

 private:
  void run(Job_request request);
  void cancel_and_join();

  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> abandoned_{false};
  mutable std::mutex mutex_;
  Status status_;
  std::optional<Outcome> outcome_;
};

}  // namespace sculpt::viewer
