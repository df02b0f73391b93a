// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench_tables.hpp"

#include <fmt/format.h>

#include <initializer_list>
#include <iostream>
#include <string>

namespace sculpt::cli {
namespace {

double stage_seconds(const nlohmann::json& stats, std::initializer_list<const char*> names) {
  double sum = 0;
  for (const auto& stage : stats["stages"]) {
    for (const char* name : names) sum += stage["name"] == name ? double(stage["seconds"]) : 0.0;
  }
  return sum;
}

// The stages every method shares; the rest are the method's own, whatever their names.
const std::initializer_list<const char*> shared_stages = {"checks", "delaunay", "poles",
                                                          "topology"};

double own_stage_seconds(const nlohmann::json& stats) {
  double sum = 0;
  for (const auto& stage : stats["stages"]) sum += double(stage["seconds"]);
  return sum - stage_seconds(stats, shared_stages);
}

}  // namespace

void print_rows(const std::vector<nlohmann::json>& rows) {
  std::cout
      << "\nWhole process: CPU seconds and peak memory of a process that reads the input and "
         "runs one job,\nless what it spends judging its result against the input's mesh.\nx DT: "
         "against the process that reads the same input and builds "
         "CGAL's Delaunay triangulation of it.\nThe stage columns (and DT core) are wall-clock "
         "seconds inside the process.\n";
  std::cout << fmt::format("\n{:<20}{:>9}{:>17}{:>17}{:>8}{:>8}{:>8}{:>8}{:>8}{:>9}{:>7}{:>8}\n",
                           "input", "n", "method", "DT core / whole", "delaun.", "poles", "method",
                           "topol.", "read", "whole s", "x DT", "MiB xDT");
  for (const auto& row : rows) {
    const auto& dt = row["delaunay_only"];
    const std::string input = row["input"].get<std::string>();
    if (dt.contains("error")) {
      std::cout << fmt::format("{:<20} failed: {}\n", input, dt["error"].get<std::string>());
      continue;
    }
    const double dt_whole = dt["process"]["cpu_seconds"];
    const double dt_mib = dt["process"]["peak_mib"];
    const std::string dt_text = fmt::format("{:.3f} / {:.3f}", double(dt["seconds"]), dt_whole);
    const auto print = [&](const std::string& label, const nlohmann::json& s) {
      if (s.contains("error")) {
        std::cout << fmt::format("{:<20}{:>9}{:>17}  failed: {}\n", input, "", label,
                                 s["error"].get<std::string>());
        return;
      }
      const double whole = s["process"]["cpu_seconds"];
      const bool staged = s.contains("stages") && !s["stages"].empty();
      const auto cell = [&](std::initializer_list<const char*> names) {
        return staged ? fmt::format("{:.3f}", stage_seconds(s, names)) : std::string("");
      };
      std::cout << fmt::format(
          "{:<20}{:>9}{:>17}{:>17}{:>8}{:>8}{:>8}{:>8}{:>8.3f}{:>9.3f}{:>7.2f}{:>8.2f}\n", input,
          row["samples"].get<std::size_t>(), label, dt_text, cell({"checks", "delaunay"}),
          cell({"poles"}), staged ? fmt::format("{:.3f}", own_stage_seconds(s)) : std::string(""),
          cell({"topology"}), double(s.value("read_seconds", 0.0)), whole, whole / dt_whole,
          double(s["process"]["peak_mib"]) / dt_mib);
    };
    for (const auto& [method, s] : row["methods"].items()) print(method, s);
    if (row.contains("advancing_front")) print("CGAL adv. front", row["advancing_front"]);
  }

  std::cout << fmt::format("\n{:<20}{:>17}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
                           "result", "method", "triangles", "non-man.", "n.-m. v", "border",
                           "unused", "pieces", "Euler(own)", "reproduced", "verdict");
  for (const auto& row : rows) {
    const bool has_reference = row["delaunay_only"].contains("reference");
    const auto print = [&](const std::string& label, const nlohmann::json& s) {
      if (s.contains("error")) return;
      const std::string euler =
          has_reference
              ? fmt::format("{}({})", s["euler_characteristic"].get<long>(),
                            row["delaunay_only"]["reference"]["euler_characteristic"].get<long>())
              : std::to_string(s["euler_characteristic"].get<long>());
      const std::string reproduced =
          s.contains("reproduced") ? fmt::format("{:.1f}%", 100 * double(s["reproduced"])) : "";
      std::cout << fmt::format(
          "{:<20}{:>17}{:>10}{:>10}{:>9}{:>9}{:>8}{:>8}{:>11}{:>10}  {}\n",
          row["input"].get<std::string>(), label, s["facets"].get<std::size_t>(),
          s["non_manifold_ridges"].get<std::size_t>(),
          s["non_manifold_vertices"].get<std::size_t>(), s["boundary_ridges"].get<std::size_t>(),
          s["unused_samples"].get<std::size_t>(), s["components"].get<std::size_t>(), euler,
          reproduced, s["manifold"].get<bool>() ? "manifold" : "DEFECTIVE");
    };
    for (const auto& [method, s] : row["methods"].items()) print(method, s);
    if (row.contains("advancing_front")) print("CGAL adv. front", row["advancing_front"]);
  }
}

void print_edits(const std::vector<nlohmann::json>& rows) {
  std::cout << "\nlive 2D edit (viewer): one sample moved, reconstructed with every stage kept "
               "(robust), Voronoi and curve scenes built; median of 21 edits\n";
  std::cout << fmt::format("{:>8}  {:>13}  {:>9}  {:>9}  {:>6}\n", "samples", "reconstruct",
                           "scenes", "per edit", "x DT");
  for (const auto& row : rows) {
    if (row.contains("error")) {
      std::cout << "edit timing failed: " << row["error"].get<std::string>() << '\n';
      continue;
    }
    const double total = double(row["reconstruct"]) + double(row["scene"]);
    std::cout << fmt::format("{:>8}  {:>10.1f} ms  {:>6.1f} ms  {:>6.1f} ms  {:>6.1f}\n",
                             row["samples"].get<int>(), 1e3 * double(row["reconstruct"]),
                             1e3 * double(row["scene"]), 1e3 * total,
                             double(row["reconstruct"]) / double(row["delaunay"]));
  }
}

void print_rendering(const nlohmann::json& measured) {
  if (measured.contains("error")) {
    std::cout << "rendering failed: " << measured["error"].get<std::string>() << '\n';
    return;
  }
  std::cout << fmt::format(
      "\nheadless render, {} triangles at 1600x1200 ({}): scene {:.2f} s, first render {:.2f} s "
      "(module, context, shaders, upload, draw), next render {:.2f} s, peak {:.0f} MiB\n",
      measured["triangles"].get<std::size_t>(), measured["renderer"].get<std::string>(),
      double(measured["scene"]), double(measured["first"]), double(measured["second"]),
      double(measured["process"]["peak_mib"]));
}

}  // namespace sculpt::cli
