// SPDX-License-Identifier: GPL-3.0-or-later
#include "gallery.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "cgal_meshes.hpp"
#include "frontend/input.hpp"
#include "frontend/pseudo_code.hpp"
#include "frontend/shot_renderer.hpp"
#include "io/atomic_file.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_folder.hpp"
#include "io/output_set.hpp"

namespace sculpt::figures {
namespace {

using frontend::Shot;

std::string input_name(const Shot& s) {
  return s.example.empty() ? std::filesystem::path(s.input).filename().string() : s.example;
}

std::string model_key(const Shot& s) {
  return input_name(s) + (s.bordered ? " (bordered" : " (closed") +
         (s.box_factor != sculpt::Options{}.box_factor ? fmt::format(", box {}", s.box_factor)
                                                       : "") +
         ")";
}

template <class Result>
std::string stage_seconds(const Result& r, const char* name) {
  for (const auto& stage : r.stats.stages) {
    if (stage.name == name) return fmt::format("{:.3f}", stage.seconds);
  }
  return "";
}

std::string table_1(
    const std::vector<std::pair<std::string, const frontend::Any_reconstruction*>>& models) {
  std::ostringstream out;
  out << "| model | n | m (or l) | conflicts | unlabelled | triangles (edges) | border | "
         "non-manifold | unused | DT s | poles s | separation s | insertion s | extraction s | "
         "total s | verdict |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [name, any] : models) {
    std::visit(
        [&](const auto& r) {
          const auto& s = r.stats;
          double extraction = 0;
          for (const auto& stage : s.stages) {
            if (stage.name == "solid" || stage.name == "surface" || stage.name == "topology")
              extraction += stage.seconds;
          }
          out << fmt::format(
              "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.3f} | {:.3f} "
              "| {} |\n",
              name, s.samples, s.inserted_poles + (std::size_t(1) << s.dimension), s.conflicts,
              s.unlabelled_poles, s.facets, s.boundary_ridges, s.non_manifold_ridges,
              s.unused_samples, stage_seconds(r, "delaunay"), stage_seconds(r, "poles"),
              stage_seconds(r, "propagation"), stage_seconds(r, "insertion"), extraction,
              s.total_seconds, verdict(s).line);
        },
        *any);
  }
  return out.str();
}

std::string table_2(
    const std::vector<std::pair<std::string, const frontend::Any_reconstruction*>>& models) {
  std::ostringstream out;
  out << "| model | n | triangles | verdict (paper) | total s | CGAL DT of the samples s | total "
         "/ DT | verdict of the tight co-cone | its total / DT | verdict of the robust method "
         "(Sculpt's default) | its total / DT |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [name, any] : models) {
    std::visit(
        [&](const auto& r) {
          constexpr int D = std::decay_t<decltype(r)>::dimension;
          const auto& s = r.stats;
          if constexpr (D == 3) {
            if (r.options.kind != Surface_kind::closed) return;
            const std::vector<Point<D>> samples(r.sites.begin(),
                                                r.sites.begin() + r.sample_count());
            const double dt = delaunay_seconds(samples);
            const auto by = [&](Method method) {
              sculpt::Options options = r.options;
              options.method = method;
              options.keep_triangulations = options.keep_solid = false;
              return reconstruct(samples, options).stats;
            };
            const Statistics tight = by(Method::tight_cocone), beyond = by(Method::robust);
            out << fmt::format(
                "| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.2f} | {} | {:.2f} | {} | {:.2f} |\n",
                name, s.samples, s.facets, verdict(s).line, s.total_seconds, dt,
                s.total_seconds / dt, verdict(tight).line, tight.total_seconds / dt,
                verdict(beyond).line, beyond.total_seconds / dt);
          }
        },
        *any);
  }
  return out.str();
}

// Fig. 5: our pseudo-code with the counts of the run the figure shows.
std::string pseudo_code_with_counts(const frontend::Any_reconstruction& any) {
  std::ostringstream out;
  std::visit(
      [&](const auto& r) {
        std::size_t seeds = 0, cube = 0, pairing = 0;
        for (const auto& e : r.propagation.events) {
          seeds += e.reason == Label_reason::convex_seed;
          cube += e.reason == Label_reason::inscribed_cube;
          pairing += e.reason == Label_reason::pairing;
        }
        out << "```\n";
        for (const char* line : frontend::pseudo_code(Method::paper).lines) out << line << '\n';
        out << "```\n\nOne run on `star`: " << r.stats.poles << " poles, " << seeds
            << " outer seeds (convex poles), " << r.propagation.events.size()
            << " labelling events (" << cube << " by an inscribed square, " << pairing
            << " by pairing), " << r.stats.conflicts << " conflicts, " << r.stats.unlabelled_poles
            << " unlabelled, " << r.stats.inserted_poles << " outer concave poles inserted.\n";
      },
      any);
  return out.str();
}

// The manifest already in the folder (a full gallery's), with the entries of `chosen` put in
// place of its own of the same figures, in figure order; just `chosen` when there is none to
// read.
nlohmann::json with_entries_of(const std::string& path, nlohmann::json chosen) {
  std::ifstream in(path);
  nlohmann::json kept = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
  if (!kept.is_array()) return chosen;
  for (auto& entry : chosen) {
    const auto same = std::find_if(kept.begin(), kept.end(), [&](const nlohmann::json& old) {
      return old.is_object() && old.value("id", "") == entry.value("id", "");
    });
    if (same != kept.end())
      *same = std::move(entry);
    else
      kept.push_back(std::move(entry));
  }
  std::stable_sort(kept.begin(), kept.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return (a.is_object() ? a.value("id", "") : "") < (b.is_object() ? b.value("id", "") : "");
  });
  return kept;
}

}  // namespace

int generate(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Figure> chosen;
  for (const auto& figure : paper_figures()) {
    if (options.only.empty() || figure.id == options.only) chosen.push_back(figure);
  }
  if (chosen.empty())
    throw io::Error("no figure '" + options.only + "' (figures are fig01 ... fig15)");
  // Every output checked before the work, and all of them or none left at the end: a failed
  // run (a full disk, an error) leaves the folder as it was, or no folder; a signal removes
  // the files (io/temporary_files.hpp) but leaves a folder the run made, empty.
  io::Output_folder folder(options.out);
  const auto in_folder = [&](const std::string& name) {
    return (std::filesystem::path(options.out) / name).string();
  };
  // One figure (--only) replaces its own entry in the folder's manifest and leaves the tables
  // and the README, which describe the whole gallery, as they are.
  std::vector<std::string> destinations = {in_folder("figures.json")};
  if (options.only.empty()) {
    for (const char* whole : {"table1.md", "table2.md", "README.md"})
      destinations.push_back(in_folder(whole));
  }
  for (const auto& figure : chosen) {
    for (const auto& image : figure.images)
      destinations.push_back(in_folder(figure.id + image.suffix + ".png"));
  }
  io::check_destinations(destinations);
  io::Output_set outputs;

  std::set<std::string> meshes;
  for (const auto& figure : chosen) {
    for (const auto& image : figure.images) {
      if (image.shot.input.rfind("cgal:", 0) == 0) meshes.insert(image.shot.input.substr(5));
    }
  }
  if (meshes.empty() && options.cgal_archive != Options{}.cgal_archive) {
    throw io::Error("--cgal-data: the figures chosen draw no CGAL mesh");
  }
  Cgal_meshes cgal(options.cgal_archive);
  cgal.unpack(meshes);

  frontend::Shot_renderer renderer;
  nlohmann::json manifest = nlohmann::json::array();
  std::vector<std::pair<std::string, const frontend::Any_reconstruction*>> models;
  std::set<std::string> seen;
  int written = 0;
  for (auto& figure : chosen) {
    nlohmann::json images = nlohmann::json::array();
    for (auto& image : figure.images) {
      Shot s = cgal.resolve(image.shot);
      s.size = options.size;
      const std::string file = figure.id + image.suffix + ".png";
      s.output = outputs.stage(in_folder(file));
      std::cerr << "sculpt figures: " << file << '\n';
      const scene::Scene scene = renderer.render(s);
      nlohmann::json layers = nlohmann::json::object();
      for (const auto& layer : scene.layers) layers[layer.id] = layer.positions.size();
      images.push_back({{"file", file},
                        {"what", image.what},
                        {"stage", s.stage},
                        {"model", model_key(s)},
                        {"layers", layers}});
      if (seen.insert(model_key(s)).second)
        models.emplace_back(model_key(s), &renderer.reconstruction(s));
      ++written;
    }
    manifest.push_back({{"id", figure.id}, {"caption", figure.caption}, {"images", images}});
  }

  const auto write = [&](const std::string& name, const std::string& text) {
    io::Atomic_file file(outputs.stage(in_folder(name)), false);
    file.stream() << text;
    file.commit();
  };
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.only.empty()) {
    write("table1.md",
          "# Table 1: experimental data of several reconstructions (this machine)\n\n"
          "m counts the box corners, as the paper does; times are of one run.\n\n" +
              table_1(models));
    write("table2.md",
          "# Table 2: closed reconstructions and their time, next to CGAL's Delaunay "
          "triangulation\n\n"
          "As the paper, the tight co-cone beside sculpting (both our own code, over the same "
          "Delaunay triangulation and poles), and Sculpt's robust default; CGAL's Delaunay "
          "triangulation of the same samples, timed in the same run, is the yardstick.\n\n" +
              table_2(models));
  } else {
    manifest = with_entries_of(in_folder("figures.json"), std::move(manifest));
  }
  write("figures.json", manifest.dump(2) + "\n");

  if (options.only.empty()) {
    std::ostringstream gallery;
    gallery << "# The paper's figures, regenerated\n\n"
            << "Kuo & Yau (2003), redrawn by Sculpt from its own reconstructions, headless "
               "(OSMesa, llvmpipe). "
            << "Regenerate with `build/sculpt figures --out figures` or `cmake --build build "
               "--target figures` "
            << fmt::format("({} images and two tables in {:.0f} s on this machine). ", written,
                           seconds)
            << "Colours follow the paper: samples green, inner poles red, outer concave poles blue "
               "(2D) "
            << "or orange (3D), Delaunay edges blue, Voronoi edges green.\n\n"
            << "Tables: [Table 1](table1.md) (per model: n, m, conflicts, time of each stage), "
            << "[Table 2](table2.md) (closed models by sculpting and the tight co-cone, against "
               "CGAL's Delaunay time).\n\n";
    for (const auto& figure : chosen) {
      gallery << "## " << figure.caption << "\n\n";
      for (const auto& image : figure.images) {
        gallery << "![" << figure.id << image.suffix << ": " << image.what << "](" << figure.id
                << image.suffix << ".png) ";
      }
      gallery << "\n\n> " << figure.sentence << "\n\n";
      // Where our input contradicts the caption, said before the panels, as the tour does.
      if (!figure.contradiction.empty())
        gallery << "**Differs from the paper:** " << figure.contradiction << "\n\n";
      for (const auto& image : figure.images) {
        gallery << "- ";
        if (!image.suffix.empty()) gallery << "(" << image.suffix << ") ";
        gallery << "**" << image.what << ".** " << image.why << "\n";
      }
      gallery << "\nData: " << figure.data << ".";
      if (!figure.differences.empty()) gallery << " Differs from the paper: " << figure.differences;
      gallery << " In the viewer, panel by panel: `sculpt-view --figure " << figure.id << "`.";
      gallery << "\n\n";
      if (figure.id == "fig05") {
        const Shot& s = figure.images.front().shot;
        gallery << pseudo_code_with_counts(renderer.reconstruction(s)) << "\n";
      }
    }
    write("README.md", gallery.str());
  }
  outputs.commit();
  folder.keep();
  std::cerr << fmt::format("sculpt figures: {} images in {} ({:.1f} s)\n", written, options.out,
                           seconds);
  return written;
}

}  // namespace sculpt::figures
