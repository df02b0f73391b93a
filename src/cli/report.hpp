// SPDX-License-Identifier: GPL-3.0-or-later
// What `sculpt reconstruct` tells the user: the stages with their times and memory, and the
// statistics of the result, as a table on standard output or as JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <sculpt/sculpt.hpp>
#include <string>

#include "frontend/statistics_json.hpp"

namespace sculpt::cli {

using frontend::surface_rule_name;

struct Run_description {
  std::string input;
  std::string rule;
  double box_factor = Options{}.box_factor;
  double read_seconds = 0;
  double write_seconds = 0;
};

void print_report(std::ostream& out, const Statistics& stats, const Run_description& run);
nlohmann::json report_json(const Statistics& stats, const Run_description& run);

}  // namespace sculpt::cli
