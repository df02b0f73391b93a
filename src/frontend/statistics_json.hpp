// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of a reconstruction as JSON, the fields `sculpt reconstruct --stats` writes about
// the result (the command adds its input, its read and write times): shared by the command line
// and the Python module, so that both name every number the same way.
#pragma once

#include <nlohmann/json.hpp>
#include <sculpt/sculpt.hpp>
#include <string>

namespace sculpt::frontend {

// The rule that made the surface: a surface rule, the robust method's carve (a carved surface
// comes from no surface rule), nearest neighbours (open curves), or the method's own name.
std::string surface_rule_name(const Options& options, int dimension);

// The method, the verdict, the counts and the stage timings. The caller adds how the run was asked
// for (kind, rule, box factor: surface_rule_name).
nlohmann::json statistics_json(const Statistics& stats);

}  // namespace sculpt::frontend
