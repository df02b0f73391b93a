// SPDX-License-Identifier: GPL-3.0-or-later
// Temporary files of a run, removed if the run is interrupted: a SIGINT, SIGTERM or SIGHUP while
// writing leaves no half-written file behind (the outputs themselves appear only by rename).
#pragma once

#include <string>

namespace sculpt::io {

// Registers a temporary path (removed on a signal) or forgets it (written out, or removed).
void register_temporary(const std::string& path);
void forget_temporary(const std::string& path);

// Installs the handlers: on a signal, every registered temporary is removed, then the signal's
// default action ends the process.
void remove_temporaries_on_signals();

}  // namespace sculpt::io
