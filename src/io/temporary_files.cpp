// SPDX-License-Identifier: GPL-3.0-or-later
#include "temporary_files.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstring>
#include <mutex>

namespace sculpt::io {
namespace {

// A fixed table, so that the handler needs neither allocation nor locks (async-signal-safe):
// a run writes a handful of files at a time.
constexpr int slots = 32;
constexpr int longest_path = 4096;
char paths[slots][longest_path];
volatile sig_atomic_t used[slots];
std::mutex table;

void remove_all(int signal) {
  for (int i = 0; i < slots; ++i) {
    if (used[i]) ::unlink(paths[i]);
  }
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

void register_temporary(const std::string& path) {
  if (path.size() >= longest_path) return;
  std::lock_guard<std::mutex> lock(table);
  for (int i = 0; i < slots; ++i) {
    if (used[i]) continue;
    std::memcpy(paths[i], path.c_str(), path.size() + 1);
    used[i] = 1;
    return;
  }
}

void forget_temporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(table);
  for (int i = 0; i < slots; ++i) {
    if (used[i] && path == paths[i]) {
      used[i] = 0;
      return;
    }
  }
}

void remove_temporaries_on_signals() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal, remove_all);
}

}  // namespace sculpt::io
