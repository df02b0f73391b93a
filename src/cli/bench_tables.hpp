// SPDX-License-Identifier: GPL-3.0-or-later
// The tables `sculpt bench` prints on standard output, from the rows its measuring processes
// returned: time and memory beside CGAL's Delaunay triangulation, what each result is, the
// viewer's live 2D edit and a headless render.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

namespace sculpt::cli {

// The inputs' rows (measure_input): the times and memory, then what each result is.
void print_rows(const std::vector<nlohmann::json>& rows);
// The edit jobs' rows: the live 2D edit's times by number of samples.
void print_edits(const std::vector<nlohmann::json>& rows);
// The render job's result, in one line.
void print_rendering(const nlohmann::json& measured);

}  // namespace sculpt::cli
