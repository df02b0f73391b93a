// SPDX-License-Identifier: GPL-3.0-or-later
// Temporary files of a run: an output is written beside its destination under a hidden name and
// renamed into place only when complete. Nothing may orphan them: a signal that would end the run
// removes them first, a file-size limit fails the write instead of killing the run, and what a
// killed run (SIGKILL, a power cut) left is removed by the next run that writes there.
#pragma once

#include <signal.h>

#include <string>

namespace sculpt::io {

// The hidden name `destination` is written under: `.NAME.sculpt-PID.EXT` in the same folder
// (same extension, so that writers choose the same format), shortened where needed so that any
// legal destination name gives a legal temporary one. Registers it (removed on a signal) and
// first removes the temporaries that dead runs left for the same destination.
std::string make_temporary(const std::string& destination);

// Registers a temporary named otherwise (a TetGen solid's companion, named after its .node).
void register_temporary(const std::string& temporary, const std::string& destination);

// Forgets a temporary (renamed into place, or removed).
void forget_temporary(const std::string& temporary);

// The destination a registered temporary stands for, else `path` itself: messages name the
// user's path, never the hidden one.
std::string destination_of(const std::string& path);

// Whether `path` is a registered temporary (a writer given one writes it directly).
bool is_temporary(const std::string& path);

// Installs the handlers: each signal whose default action ends the process (and that nobody
// else handles, as Python handles SIGINT) first removes every registered temporary; SIGXFSZ is
// ignored, so that exceeding a file-size limit fails the write (and the run, cleanly).
void remove_temporaries_on_signals();

// The signals remove_temporaries_on_signals() handles (blocked while a set of outputs is
// renamed into place).
void add_ending_signals(sigset_t& signals);

}  // namespace sculpt::io
