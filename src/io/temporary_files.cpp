// SPDX-License-Identifier: GPL-3.0-or-later
#include "temporary_files.hpp"

#include <dirent.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>

namespace sculpt::io {
namespace {

namespace fs = std::filesystem;

// The signals whose default action ends the process, SIGKILL and SIGSTOP aside (no handler can
// run), and SIGXFSZ, which is ignored instead.
constexpr int ending_signals[] = {SIGINT,  SIGTERM, SIGHUP,    SIGQUIT, SIGXCPU, SIGALRM,
                                  SIGUSR1, SIGUSR2, SIGVTALRM, SIGPROF, SIGPIPE};

// A fixed table, so that the handler needs neither allocation nor locks (async-signal-safe):
// a run writes a handful of files at a time.
constexpr int slots = 32;
constexpr int longest_path = 4096;
char paths[slots][longest_path];
volatile sig_atomic_t used[slots];

std::mutex table;
// Each temporary's destination, for messages (not read by the handler).
std::map<std::string, std::string>& destinations() {
  static std::map<std::string, std::string> by_temporary;
  return by_temporary;
}

void remove_all(int signal) {
  for (int i = 0; i < slots; ++i) {
    if (used[i]) ::unlink(paths[i]);
  }
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

constexpr const char* marker = ".sculpt-";

// The part of a destination's name that its temporaries begin with: "." and the stem, cut so
// that the whole name, with the marker, a process id and the extension, fits in NAME_MAX bytes.
// The cut never splits a UTF-8 character.
std::string temporary_prefix(const std::string& stem, const std::string& extension) {
  constexpr std::size_t longest_pid = 10;
  const std::size_t fixed = 1 + std::strlen(marker) + longest_pid + extension.size();
  std::size_t keep = fixed < NAME_MAX ? std::min(stem.size(), NAME_MAX - fixed) : 0;
  while (keep > 0 && keep < stem.size() && (static_cast<unsigned char>(stem[keep]) & 0xC0) == 0x80)
    --keep;
  return "." + stem.substr(0, keep) + marker;
}

// Removes `.STEM.sculpt-PID.EXT` files beside the destination (any extension: a TetGen solid's
// companion too) whose process is gone: a run killed beyond any handler (SIGKILL, a power cut)
// leaves them, the next run that writes there cleans up. A process that still runs keeps its file.
void remove_stale_temporaries(const fs::path& folder, const std::string& prefix) {
  DIR* directory = ::opendir(folder.empty() ? "." : folder.c_str());
  if (directory == nullptr) return;
  while (const dirent* entry = ::readdir(directory)) {
    const std::string name = entry->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::size_t digits_end = name.find_first_not_of("0123456789", prefix.size());
    const std::size_t digits =
        (digits_end == std::string::npos ? name.size() : digits_end) - prefix.size();
    if (digits == 0 || digits > 9 || (digits_end != std::string::npos && name[digits_end] != '.'))
      continue;
    const pid_t owner = static_cast<pid_t>(std::stol(name.substr(prefix.size(), digits)));
    if (owner != ::getpid() && ::kill(owner, 0) != 0 && errno == ESRCH) {
      ::unlink((folder / name).c_str());
    }
  }
  ::closedir(directory);
}

}  // namespace

void register_temporary(const std::string& temporary, const std::string& destination) {
  std::lock_guard<std::mutex> lock(table);
  destinations()[temporary] = destination;
  if (temporary.size() >= longest_path) return;
  for (int i = 0; i < slots; ++i) {
    if (used[i]) continue;
    std::memcpy(paths[i], temporary.c_str(), temporary.size() + 1);
    used[i] = 1;
    return;
  }
}

std::string make_temporary(const std::string& destination) {
  const fs::path path(destination);
  const std::string extension = path.extension().string();
  const std::string prefix = temporary_prefix(path.stem().string(), extension);
  remove_stale_temporaries(path.parent_path(), prefix);
  const std::string temporary =
      (path.parent_path() / (prefix + std::to_string(::getpid()) + extension)).string();
  register_temporary(temporary, destination);
  return temporary;
}

void forget_temporary(const std::string& temporary) {
  std::lock_guard<std::mutex> lock(table);
  destinations().erase(temporary);
  for (int i = 0; i < slots; ++i) {
    if (used[i] && temporary == paths[i]) {
      used[i] = 0;
      return;
    }
  }
}

std::string destination_of(const std::string& path) {
  std::lock_guard<std::mutex> lock(table);
  const auto found = destinations().find(path);
  return found == destinations().end() ? path : found->second;
}

bool is_temporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(table);
  return destinations().count(path) != 0;
}

void remove_temporaries_on_signals() {
  for (int signal : ending_signals) {
    struct sigaction current {};
    // Only where the default action would end the process: a handler someone else installed
    // (Python's for SIGINT) or an ignored signal stays as it is.
    if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) {
      ::signal(signal, remove_all);
    }
  }
  ::signal(SIGXFSZ, SIG_IGN);
}

void add_ending_signals(sigset_t& signals) {
  for (int signal : ending_signals) sigaddset(&signals, signal);
}

}  // namespace sculpt::io
