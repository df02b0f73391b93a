// SPDX-License-Identifier: GPL-3.0-or-later
// What `sculpt` and `sculpt-view` share about their command lines: the exit codes, and usage
// errors as one line on stderr with exit code 2 (CLI11 prints two lines and exits 105 and up).
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sculpt/sculpt.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "frontend/closest_name.hpp"
#include "frontend/command_line_text.hpp"

namespace sculpt::frontend {

enum Exit_code : int {
  exit_success = 0,
  exit_bad_input = 1,         // a file that cannot be read, points that cannot be reconstructed,
                              // an output that cannot be written
  exit_bad_usage = 2,         // an unknown option, a bad value, a missing argument
  exit_defective_result = 3,  // --require-manifold, and the result is not a 2-manifold
};

inline const char* exit_codes_help =
    "Exit codes: 0 success; 1 bad input (unreadable or malformed file, points that cannot be "
    "reconstructed, an output that cannot be written); 2 bad usage; 3 with --require-manifold, "
    "a result that is not a 2-manifold (written all the same). Every failure is one line on "
    "stderr, and no output file is left behind.";

// The --method option's help: every method's name and a few words about it, the default first.
inline std::string methods_help() {
  std::string help;
  for (const char* name : method_names()) {
    Method method;
    parse_method(name, method);
    help += (help.empty() ? "" : "; ") + std::string(name) +
            (method == Options{}.method ? " (default)" : "") + ": " + describe(method);
  }
  return help;
}

// Why --solid (or solid= in Python) is refused for a method that builds no solid.
inline std::string no_solid_message(Method method) {
  std::string builders;
  for (const char* name : method_names()) {
    Method other;
    parse_method(name, other);
    if (builds_solid(other)) builders += std::string(builders.empty() ? "" : ", ") + name;
  }
  return std::string("the method ") + to_string(method) + " builds no solid (" + builders + " do)";
}

// A positive finite length (--alpha), said in one short line when it is not.
inline CLI::Validator positive_length() {
  return CLI::Validator(
      [](std::string& text) {
        try {
          std::size_t used = 0;
          const double value = std::stod(text, &used);
          if (used == text.size() && value > 0 && std::isfinite(value)) return std::string();
        } catch (const std::exception&) {
        }
        return "'" + text + "' is not a positive length";
      },
      "LENGTH");
}

// A count (--torus N): CLI::PositiveNumber's message prints the largest double in full.
inline CLI::Validator whole_number_above_zero() {
  return CLI::Validator(
      [](std::string& text) {
        try {
          std::size_t used = 0;
          const long value = std::stol(text, &used);
          if (used == text.size() && value > 0 && value <= 2'000'000'000) return std::string();
        } catch (const std::exception&) {
        }
        return "'" + text + "' is not a whole number from 1 to 2,000,000,000";
      },
      "N");
}

// A scale (--font-scale, --picture-scale) from low to high: CLI::Range lets NaN through (every
// comparison with it is false).
inline CLI::Validator scale_from(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (*end == '\0' && value >= low && value <= high) return std::string();
        char range[64];
        std::snprintf(range, sizeof range, "%g to %g", low, high);
        return "'" + text + "' is not a scale from " + range;
      },
      "");  // unnamed: the help shows the option's type alone (FLOAT)
}

// A mistake in the arguments themselves (exit code 2), found before any work is done.
class Usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses the command line; an exit code if the program should stop now (help, version, or a
// usage error reported in one line), nothing if it should run.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                             const std::string& program) {
  // A mistyped command: CLI11 would only say that one is required.
  const auto all = app.get_subcommands({});
  const bool known = argc > 1 && std::any_of(all.begin(), all.end(), [&](const CLI::App* command) {
                       return command->check_name(argv[1]);
                     });
  if (!all.empty() && argc > 1 && argv[1][0] != '-' && !known) {
    std::vector<std::string> names;  // the commands --help lists, not the hidden ones
    std::string listed;
    for (const CLI::App* command : all) {
      if (command->get_description().empty()) continue;
      names.push_back(command->get_name());
      listed += (listed.empty() ? "" : ", ") + names.back();
    }
    // A file given first is most likely a file to reconstruct.
    std::error_code no_file;
    const bool reconstructs = std::count(names.begin(), names.end(), "reconstruct") > 0;
    const std::string hint =
        reconstructs && std::filesystem::is_regular_file(argv[1], no_file)
            ? " (did you mean '" + program + " reconstruct " + one_line(argv[1]) + "'?)"
            : did_you_mean(argv[1], names);
    std::cerr << program << ": usage error: no command '" << one_line(argv[1]) << "'" << hint
              << "; the commands are " << listed << " (see " << program << " --help)\n";
    return exit_bad_usage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // An unknown option first: its value, taken for an input, would make CLI11 blame another.
    CLI::App* command = &app;
    for (CLI::App* sub : all) {
      if (argc > 1 && sub->check_name(argv[1])) command = sub;
    }
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--") break;
      if (word.size() < 3 || word.compare(0, 2, "--") != 0) continue;
      const std::string name = word.substr(0, word.find('='));
      if (name == "--help" || command->get_option_no_throw(name) != nullptr) continue;
      std::vector<std::string> names;
      for (const CLI::Option* option : command->get_options()) {
        for (const std::string& long_name : option->get_lnames()) names.push_back("--" + long_name);
      }
      std::cerr << program << ": usage error: no option '" << one_line(name) << "'"
                << did_you_mean(name, names) << " (see " << program << " "
                << (command == &app ? "" : command->get_name() + " ") << "--help)\n";
      return exit_bad_usage;
    }
    std::cerr << program << ": usage error: " << one_line(e.what()) << " (see " << program
              << " --help)\n";
    return exit_bad_usage;
  }
  return std::nullopt;
}

}  // namespace sculpt::frontend
