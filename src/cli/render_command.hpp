// SPDX-License-Identifier: GPL-3.0-or-later
// `sculpt render`: pictures of any stage, headless (OSMesa), one shot or a list of shots in
// one process.
#pragma once

#include <string>
#include <vector>

#include "frontend/shots.hpp"

namespace CLI {
class App;
}

namespace sculpt::cli {

using frontend::Shot;

struct Render_arguments {
  Shot shot;
  std::string shots_file;       // JSON: {"shots": [ {...}, ... ]} with the fields of Shot
  CLI::App* command = nullptr;  // the subcommand: which options were given
};

void add_render_command(CLI::App& app, Render_arguments& args);
int run_render(const Render_arguments& args);

}  // namespace sculpt::cli
