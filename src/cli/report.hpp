// What `sculpt reconstruct` tells the user: the stages with their times and memory, and the
// statistics of the result, as a table on standard output or as JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <sculpt/sculpt.hpp>
#include <string>

namespace sculpt::cli {

struct Run_description {
  std::string input;
  std::string rule;
  std::string kind;
  double box_factor = Options{}.box_factor;
  double read_seconds = 0;
  double write_seconds = 0;
};

// The rule that made the surface, for the report: a surface rule, or the robust method's carve
// (a carved surface comes from no surface rule).
std::string surface_rule_name(const Options& options, int dimension);

void print_report(std::ostream& out, const Statistics& stats, const Run_description& run);
nlohmann::json report_json(const Statistics& stats, const Run_description& run);

}  // namespace sculpt::cli
