// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction the viewer asks for: its input (a file, an example or points edited by hand)
// and options, run to an outcome (the reconstruction, or the one-line error the command line
// would give). Written as JSON, it crosses into the browser's reconstruction worker.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "frontend/input.hpp"

namespace sculpt::frontend {

struct Reconstruction_request {
  std::string path, example;  // one of them, or edited points
  // Points edited in the viewer (2D), with what they were edited from and the edit count.
  std::shared_ptr<const std::vector<Point<2>>> edited_points;
  std::string edited_from;
  int edits = 0;
  int dimension = 0;              // 0: as the file says
  bool merge_duplicates = false;  // drop a file's repeated points instead of refusing them
  std::string shown_as;  // how to name the input when not by its path (e.g. "CGAL's fandisk.off")
  Options options;       // the progress callback is the runner's, not the request's
};

struct Reconstruction_outcome {
  std::optional<Any_reconstruction> reconstruction;
  std::string description;  // the input, as the statistics panel names it
  std::string error;        // empty on success; "cancelled" when cancelled
};

// Reads the input and reconstructs it with every stage kept, reporting to `progress` (false from
// it cancels). Never throws: errors become the outcome's one-line message.
Reconstruction_outcome run_request(Reconstruction_request request,
                                   const std::function<bool(const Progress&)>& progress);

nlohmann::json to_json(const Reconstruction_request& request);
// Throws io::Error with a one-line message for JSON that is not a request.
Reconstruction_request request_from_json(const nlohmann::json& json);

}  // namespace sculpt::frontend
