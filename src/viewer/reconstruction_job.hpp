// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a reconstruction off the UI thread: loading the input and every stage, with the stage
// name and progress readable at any time, and a cancel that returns at once (the UI stays live).
// The platform's runner does the work (platform/): a thread on the desktop, a Web Worker in the
// browser, whose WebAssembly cannot share the page's memory without cross-origin isolation.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "frontend/reconstruction_request.hpp"

namespace sculpt::viewer {

using Any_reconstruction = frontend::Any_reconstruction;
using Job_request = frontend::Reconstruction_request;

class Reconstruction_job {
 public:
  virtual ~Reconstruction_job() = default;

  virtual void start(Job_request request) = 0;  // cancels and replaces a running job
  // Asks the job to stop; returns at once.
  virtual void request_cancel() = 0;
  // Cancels a running job and drops whatever it ends with: the viewer has moved on.
  virtual void abandon() = 0;
  virtual bool running() const = 0;
  // Ended, with an outcome nobody has taken yet.
  virtual bool outcome_waiting() const = 0;

  struct Status {
    std::string stage;
    double fraction = 0;  // within the stage
    double overall = 0;   // across the whole reconstruction
  };
  virtual Status status() const = 0;

  // Once the job has ended: its reconstruction and input description, or its error message.
  using Outcome = frontend::Reconstruction_outcome;
  virtual std::optional<Outcome> take_outcome() = 0;
};

// The platform's job runner.
std::unique_ptr<Reconstruction_job> make_reconstruction_job();

}  // namespace sculpt::viewer
