#include "reconstruction_job.hpp"

#include "frontend/input.hpp"
#include "io/io_error.hpp"

namespace sculpt::viewer {

Reconstruction_job::~Reconstruction_job() {
  cancel_and_join();
}

void Reconstruction_job::cancel_and_join() {
  cancelled_ = true;
  if (thread_.joinable()) thread_.join();
}

void Reconstruction_job::start(Job_request request) {
  cancel_and_join();
  cancelled_ = abandoned_ = false;
  running_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = {"reading", 0};
    outcome_.reset();
  }
  thread_ = std::thread(&Reconstruction_job::run, this, std::move(request));
}

Reconstruction_job::Status Reconstruction_job::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

std::optional<Reconstruction_job::Outcome> Reconstruction_job::take_outcome() {
  if (running_) return std::nullopt;
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<Outcome> outcome;
  outcome.swap(outcome_);
  if (abandoned_) return std::nullopt;
  return outcome;
}

void Reconstruction_job::run(Job_request request) {
  Outcome outcome;
  try {
    frontend::Input input;
    if (request.edited_points) {
      input.points = *request.edited_points;
      input.description = std::to_string(request.edited_points->size()) +
                          " samples: " + request.edited_from + ", " +
                          std::to_string(request.edits) + (request.edits == 1 ? " edit" : " edits");
    } else {
      input = frontend::load_input(request.path, request.example, request.dimension,
                                   request.merge_duplicates);
    }
    outcome.description = input.description;
    if (!request.shown_as.empty() && input.description.rfind(request.path, 0) == 0) {
      outcome.description = request.shown_as + input.description.substr(request.path.size());
    }
    request.options.keep_triangulations = true;
    request.options.progress = [this](const Progress& progress) {
      std::lock_guard<std::mutex> lock(mutex_);
      status_ = {progress.stage ? progress.stage : "", progress.fraction, progress.overall};
      return !cancelled_;
    };
    outcome.reconstruction = std::visit(
        [&](const auto& points) -> Any_reconstruction {
          return reconstruct(points, request.options);
        },
        input.points);
  } catch (const Cancelled&) {
    outcome.error = "cancelled";
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome_ = std::move(outcome);
  }
  running_ = false;
}

}  // namespace sculpt::viewer
