#include "figures.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include "frontend/input.hpp"
#include "frontend/pseudo_code.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace sculpt::figures {
namespace {

using frontend::Shot;

// A shot of `input` ("example:NAME" or "cgal:FILE.off") at `stage`.
Shot shot(const std::string& input, const char* stage) {
  Shot s;
  s.method = to_string(Method::paper);  // the paper's figures show the paper's algorithm
  if (input.rfind("example:", 0) == 0) {
    s.example = input.substr(8);
  } else {
    s.input = input;  // resolved when the CGAL meshes are unpacked
  }
  s.stage = stage;
  return s;
}

Shot bordered(Shot s, double box_factor = sculpt::Options{}.box_factor) {
  s.bordered = true;
  s.box_factor = box_factor;
  return s;
}

Shot with_layers(Shot s, std::vector<std::string> layers) {
  s.layers = std::move(layers);
  return s;
}

Shot zoomed(Shot s, float zoom) {
  s.zoom = zoom;
  s.wireframe = true;
  return s;
}

// Looking into a hemisphere's opening (its rim lies in the plane z = 0, the dome towards +z).
Shot from_below(Shot s) {
  s.yaw = 3.14159265f;
  s.pitch = 0.45f;
  return s;
}

Shot wire(Shot s) {
  s.wireframe = true;
  return s;
}

}  // namespace

const std::vector<Figure>& paper_figures() {
  static const std::vector<Figure> figures = [] {
    std::vector<Figure> f;
    f.push_back({"fig01",
                 "Fig. 1 The illustration of the sculpting idea in 3D space.",
                 "the built-in `bumpy` (6000 samples on a sphere with dents and bumps)",
                 "The paper's model is not available; a bumpy sphere shows the concavities well.",
                 {{"a", "the convex hull: all-sample tetrahedra of DT(S + BBV)",
                   shot("example:bumpy", "hull")},
                  {"b", "the concavities sculpted out", shot("example:bumpy", "surface")}}});
    f.push_back(
        {"fig02",
         "Fig. 2 The illustration of the sculpting idea in 2D plane.",
         "the built-in `blob` (150 samples on a smooth closed curve)",
         "Our DT also has the box corners BBV, so (a) shows edges leaving the frame; (b) is "
         "the sculpted solid, the triangles left when the outer concave poles are in.",
         {{"a", "samples and their Delaunay triangulation", shot("example:blob", "delaunay")},
          {"b", "the outside triangles removed", shot("example:blob", "solid")},
          {"c", "the boundary", shot("example:blob", "surface")}}});
    {
      Shot medial = with_layers(shot("example:blob-dense", "propagation"),
                                {"polar-balls", "inner-poles", "outer-poles", "samples"});
      medial.ball_every = 16;
      f.push_back({"fig03",
                   "Fig. 3 The internal and external medial axis and the medial circles of a "
                   "closed curve in two dimensions.",
                   "the built-in `blob-dense` (600 samples)",
                   "The medial axis is approximated by the poles of a dense sample (inner red, "
                   "outer blue); one polar circle in 16 is drawn.",
                   {{"", "inner and outer poles with polar circles", medial}}});
    }
    {
      Shot pair = with_layers(shot("example:star", "poles"),
                              {"poles", "samples", "focus-balls", "focus-cubes", "focus-poles"});
      pair.focus_sample = 37;
      f.push_back({"fig04",
                   "Fig. 4 (a) The distribution of all the polar circles (black circles) centered "
                   "at the poles (red points shown in (b)) in 2D plane. (b) The illustration of a "
                   "pair of polar circles and its pair of corresponding inscribed squares.",
                   "the built-in `star` (200 samples)",
                   "",
                   {{"a", "all polar circles", shot("example:star", "poles")},
                    {"b", "a sample's two polar circles and their inscribed squares", pair}}});
    }
    {
      Shot midway = shot("example:star", "propagation");
      midway.step = 160;
      f.push_back(
          {"fig05",
           "Fig. 5 The detailed pseudo-code for the pole-separation procedure.",
           "the built-in `star`; the pseudo-code below is the one our implementation runs",
           "The paper's pseudo-code is missing from its text; ours is written out in the "
           "gallery with the counts of one run. The picture is the separation after 160 "
           "labelling events: the pole just labelled and the ball and square that labelled it.",
           {{"", "the pole separation after 160 events", midway}}});
    }
    f.push_back({"fig06",
                 "Fig. 6 An example of a two-dimensional closed curve reconstruction.",
                 "the built-in `star` (200 samples)",
                 "",
                 {{"a", "the samples S", shot("example:star", "samples")},
                  {"b", "the Voronoi diagram", shot("example:star", "voronoi")},
                  {"c", "separated poles: inner (red) and outer concave (blue)",
                   shot("example:star", "outer-concave")},
                  {"d", "DT(S + OUP)", shot("example:star", "sculpted-delaunay")},
                  {"e", "the extracted curve", shot("example:star", "surface")}}});
    f.push_back(
        {"fig07",
         "Fig. 7 An example of a three-dimensional closed surface reconstruction (a torso model).",
         "the built-in `torso`",
         "A generated torso-like blob stands in for the paper's scan.",
         {{"a", "the samples", shot("example:torso", "samples")},
          {"b", "inner poles (red) and outer concave poles (orange)",
           shot("example:torso", "outer-concave")},
          {"c", "the shaded surface", shot("example:torso", "surface")},
          {"d", "a zoom", zoomed(shot("example:torso", "surface"), 0.4f)}}});
    f.push_back(
        {"fig08",
         "Fig. 8 An example of the effect of all the concave poles on the creation of the "
         "boundary (a foot).",
         "the built-in `saddle` (z = x^2 - y^2, 40 x 40 jittered samples)",
         "The saddle stands in for the foot. A hemisphere would show it less well: its "
         "opening is mostly capped even when bordered (only 13 border edges; see Fig. 13a "
         "and Table 1), because facets across it have an outer apex and no inserted pole "
         "breaks them.",
         {{"a", "all concave poles UP inserted: inner (red) and outer (orange)",
           bordered(shot("example:saddle", "outer-concave"))},
          {"b", "closed: the sheet breaks into the skins of thin slivers, with no border anywhere",
           wire(shot("example:saddle", "surface"))},
          {"c", "bordered: the border is created",
           wire(bordered(shot("example:saddle", "surface")))}}});
    f.push_back({"fig09",
                 "Fig. 9 An example of a three-dimensional bordered surface reconstruction (a "
                 "hyper sheet).",
                 "the built-in `saddle` (z = x^2 - y^2, 40 x 40 jittered samples)",
                 "",
                 {{"a", "the samples", bordered(shot("example:saddle", "samples"))},
                  {"b", "poles of both sides (red, orange)",
                   bordered(shot("example:saddle", "outer-concave"))},
                  {"c", "the shaded surface", bordered(shot("example:saddle", "surface"))},
                  {"d", "a zoom", bordered(zoomed(shot("example:saddle", "surface"), 0.4f))}}});
    f.push_back(
        {"fig10",
         "Fig. 10 The reconstruction from the sample points with uneven distribution (a rocker "
         "arm).",
         "the built-in `bumpy` (6000 samples) and `bumpy-nonuniform` (its +x side thinned 3:1)",
         "A bumpy sphere stands in for the rocker arm.",
         {{"a", "uniform sampling", wire(shot("example:bumpy", "surface"))},
          {"b", "non-uniform sampling", wire(shot("example:bumpy-nonuniform", "surface"))},
          {"c", "a zoom on the thinned side",
           zoomed(shot("example:bumpy-nonuniform", "surface"), 0.5f)}}});
    f.push_back(
        {"fig11",
         "Fig. 11 An example of the effect of poles on the reconstruction of the geometric sharp "
         "features (a shoe model).",
         "CGAL's `fandisk.off` (6475 vertices)",
         "fandisk stands in for the shoe. Its CAD sampling gives conflicts and non-manifold "
         "edges at sharp edges (Table 1).",
         {{"", "sharp edges and corners", wire(shot("cgal:fandisk.off", "surface"))}}});
    f.push_back({"fig12",
                 "Fig. 12 Several examples of closed surface reconstruction. (a) A three-hole "
                 "model. (b) An oil pump model. (c) A hand model. (d) A baby dragon model.",
                 "the built-in `three-holes` and `torus-knot`, CGAL's `hand.off` and "
                 "`ChineseDragon-10kv.off`",
                 "A tube around a torus knot stands in for the oil pump; CGAL's Chinese dragon for "
                 "the baby dragon.",
                 {{"a", "three holes", shot("example:three-holes", "surface")},
                  {"b", "torus-knot tube", shot("example:torus-knot", "surface")},
                  {"c", "hand", shot("cgal:hand.off", "surface")},
                  {"d", "dragon", shot("cgal:ChineseDragon-10kv.off", "surface")}}});
    f.push_back(
        {"fig13",
         "Fig. 13 Several examples of bordered surfaces reconstruction. (a) A hand model. (b) A "
         "shampoo bottle model. (c) A monkey bar. (d) A golf club model. (e) An automobile "
         "exterior surface.",
         "the built-in `hemisphere`, `saddle` and `monkey-saddle` (box factor 1.5)",
         "The paper's scans are not available; generated sheets stand in. The hemisphere, seen "
         "from below, keeps only a small hole of its opening (13 border edges). The monkey saddle "
         "needs a box factor of 1.5: with 5, its flat centre has both poles near the box, "
         "and 860 non-manifold edges appear.",
         {{"a", "hemisphere", from_below(bordered(shot("example:hemisphere", "surface")))},
          {"b", "saddle", bordered(shot("example:saddle", "surface"))},
          {"c", "monkey saddle", bordered(wire(shot("example:monkey-saddle", "surface")), 1.5)}}});
    f.push_back({"fig14",
                 "Fig. 14 The comparison of our proposed algorithm with the power crust algorithm. "
                 "(a) The reconstruction from the proposed algorithm.",
                 "CGAL's `knot1.off` (3200 vertices)",
                 "Our side only: the power crust is not run here. Our output's vertices are "
                 "exactly the samples.",
                 {{"", "our reconstruction", wire(shot("cgal:knot1.off", "surface"))}}});
    f.push_back({"fig15",
                 "Fig. 15 Top row is a knot and bottom row is a femur. (a) The reconstruction from "
                 "the proposed algorithm.",
                 "CGAL's `knot1.off` and `femur.off`",
                 "Our column only: the co-cone programs are not run here. femur shows non-manifold "
                 "edges (Table 1).",
                 {{"a", "knot", shot("cgal:knot1.off", "surface")},
                  {"b", "femur", shot("cgal:femur.off", "surface")}}});
    return f;
  }();
  return figures;
}

namespace {

std::string input_name(const Shot& s) {
  return s.example.empty() ? std::filesystem::path(s.input).filename().string() : s.example;
}

std::string model_key(const Shot& s) {
  return input_name(s) + (s.bordered ? " (bordered" : " (closed") +
         (s.box_factor != sculpt::Options{}.box_factor ? fmt::format(", box {}", s.box_factor)
                                                       : "") +
         ")";
}

// Unpacks the CGAL meshes the figures use into a folder of their own.
std::string unpack_meshes(const std::string& archive, const std::set<std::string>& meshes) {
  if (meshes.empty()) return "";
  if (!std::filesystem::exists(archive)) {
    throw io::Error(archive +
                    " is missing: install Debian's libcgal-demo (scripts/install-dependencies)");
  }
  const auto folder =
      std::filesystem::temp_directory_path() / ("sculpt-figures-" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  std::string command = "tar -xzf '" + archive + "' -C '" + folder.string() + "'";
  for (const auto& mesh : meshes) command += " data/meshes/" + mesh;
  if (std::system(command.c_str()) != 0)
    throw io::Error("cannot unpack the CGAL meshes from " + archive);
  return (folder / "data" / "meshes").string();
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
         "/ DT | verdict of the robust method (Sculpt's default) | its total / DT |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
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
            sculpt::Options robust = r.options;
            robust.method = Method::robust;
            robust.keep_triangulations = false;
            const Statistics beyond = reconstruct(samples, robust).stats;
            out << fmt::format("| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.2f} | {} | {:.2f} |\n",
                               name, s.samples, s.facets, verdict(s).line, s.total_seconds, dt,
                               s.total_seconds / dt, verdict(beyond).line,
                               beyond.total_seconds / dt);
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

}  // namespace

int generate(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Figure> chosen;
  for (const auto& figure : paper_figures()) {
    if (options.only.empty() || figure.id == options.only) chosen.push_back(figure);
  }
  if (chosen.empty())
    throw io::Error("no figure '" + options.only + "' (figures are fig01 ... fig15)");
  std::filesystem::create_directories(options.out);

  std::set<std::string> meshes;
  for (const auto& figure : chosen) {
    for (const auto& image : figure.images) {
      if (image.shot.input.rfind("cgal:", 0) == 0) meshes.insert(image.shot.input.substr(5));
    }
  }
  const std::string mesh_folder = unpack_meshes(options.cgal_archive, meshes);

  frontend::Shot_renderer renderer;
  nlohmann::json manifest = nlohmann::json::array();
  std::vector<std::pair<std::string, const frontend::Any_reconstruction*>> models;
  std::set<std::string> seen;
  int written = 0;
  for (auto& figure : chosen) {
    nlohmann::json images = nlohmann::json::array();
    for (auto& image : figure.images) {
      Shot s = image.shot;
      if (s.input.rfind("cgal:", 0) == 0) s.input = mesh_folder + "/" + s.input.substr(5);
      s.size = options.size;
      const std::string file = figure.id + image.suffix + ".png";
      s.output = (std::filesystem::path(options.out) / file).string();
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
  if (!mesh_folder.empty())
    std::filesystem::remove_all(std::filesystem::path(mesh_folder).parent_path().parent_path());

  const auto write = [&](const std::string& name, const std::string& text) {
    io::Atomic_file file((std::filesystem::path(options.out) / name).string(), false);
    file.stream() << text;
    file.commit();
  };
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write("table1.md",
        "# Table 1: experimental data of several reconstructions (this machine)\n\n"
        "m counts the box corners, as the paper does; times are of one run.\n\n" +
            table_1(models));
  write(
      "table2.md",
      "# Table 2: closed reconstructions and their time, next to CGAL's Delaunay triangulation\n\n"
      "The paper compares with the tight co-cone, which is not run here: our side only, with "
      "CGAL's Delaunay triangulation of the same samples, timed in the same run, as the "
      "yardstick.\n\n" +
          table_2(models));
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
            << "[Table 2](table2.md) (closed models against CGAL's Delaunay time).\n\n";
    for (const auto& figure : chosen) {
      gallery << "## " << figure.caption << "\n\n";
      for (const auto& image : figure.images) {
        gallery << "![" << figure.id << image.suffix << ": " << image.what << "](" << figure.id
                << image.suffix << ".png) ";
      }
      gallery << "\n\n";
      for (const auto& image : figure.images) {
        if (!image.suffix.empty()) gallery << "(" << image.suffix << ") " << image.what << ". ";
      }
      gallery << "\n\nData: " << figure.data << ".";
      if (!figure.differences.empty()) gallery << " Differs from the paper: " << figure.differences;
      gallery << "\n\n";
      if (figure.id == "fig05") {
        const Shot& s = figure.images.front().shot;
        gallery << pseudo_code_with_counts(renderer.reconstruction(s)) << "\n";
      }
    }
    write("README.md", gallery.str());
  }
  std::cerr << fmt::format("sculpt figures: {} images in {} ({:.1f} s)\n", written, options.out,
                           seconds);
  return written;
}

}  // namespace sculpt::figures
