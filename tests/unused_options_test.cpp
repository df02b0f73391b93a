// SPDX-License-Identifier: GPL-3.0-or-later
// Every option that would do nothing where it is given is refused in one line that says where
// it applies (frontend/option_use.hpp), through the `sculpt` command: a user who sets --alpha on
// the robust method must not believe the result changed. And each refused option still works
// where it does apply.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "file_support.hpp"
#include "sculpt_process.hpp"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

struct Refusal {
  std::vector<std::string> arguments;
  std::string says;  // a part of the one line
  int exit_code = 2;
};

// The inputs, in a folder of the test's own (ctest runs the tests side by side).
fs::path inputs_folder(const std::string& name) {
  const fs::path folder = testing::fresh_folder("unused-options/" + name);
  std::string circle, sphere;
  for (int i = 0; i < 100; ++i) {
    const double a = 2 * M_PI * i / 100;
    circle += fmt::format("{:.17g} {:.17g}\n", std::cos(a), std::sin(a));
  }
  sphere = testing::sphere_points_text(500);
  testing::write_file("unused-options/" + name + "/circle.xy", circle);
  testing::write_file("unused-options/" + name + "/sphere.xyz", sphere);
  testing::write_file("unused-options/" + name + "/camera3.json",
                      R"({"dimension": 3, "target": [0, 0, 0], "distance": 3, "yaw": 0.6,
                          "pitch": 0.35})");
  testing::write_file(
      "unused-options/" + name + "/tetrahedron.off",
      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  testing::write_file("unused-options/" + name + "/shots.json",
                      R"({"shots": [{"example": "star", "stag": "poles", "output": "a.png"}]})");
  return folder;
}

TEST(Unused_options, AreRefusedInOneLineThatSaysWhereTheyApply) {
  const fs::path folder = inputs_folder("refused");
  // Exit code 2 for a usage error of the command line; 1 for what a file says (a shots file,
  // a camera file).
  const std::vector<Refusal> refusals = {
      // The reconstruction's options, by method and kind.
      {{"reconstruct", "sphere.xyz", "--alpha", "0.3", "-o", "s.ply"}, "--alpha is the radius"},
      {{"reconstruct", "sphere.xyz", "--closed", "--rule", "extraction", "-o", "s.ply"},
       "robust carves a closed one"},
      {{"reconstruct", "sphere.xyz", "--method", "crust", "--rule", "skin", "-o", "s.ply"},
       "crust has its own"},
      {{"reconstruct", "sphere.xyz", "--closed", "--seed-sample", "3", "-o", "s.ply"},
       "a closed one starts from every convex pole"},
      {{"reconstruct", "sphere.xyz", "--method", "paper", "--seed-sample", "3", "-o", "s.ply"},
       "a closed one starts from every convex pole"},
      {{"reconstruct", "sphere.xyz", "--method", "crust", "--bordered", "--seed-sample", "3", "-o",
        "s.ply"},
       "labels no poles from a seed"},
      {{"reconstruct", "sphere.xyz", "--method", "advancing-front", "--box-factor", "20", "-o",
        "s.ply"},
       "triangulates the samples alone"},
      {{"reconstruct", "sphere.xyz", "--method", "paper", "--automatic", "-o", "s.ply"},
       "only robust chooses the kind"},
      {{"reconstruct", "sphere.xyz", "--ascii", "-o", "s.obj"}, "is text already"},
      {{"reconstruct", "--example", "torus", "--dim", "2", "-o", "s.ply"}, "its own dimension"},
      {{"reconstruct", "--example", "torus", "--merge-duplicates", "-o", "s.ply"}, "has none"},
      // The drawing options, by what the picture draws.
      {{"render", "sphere.xyz", "--stage", "poles", "--step", "5", "-o", "x.png"},
       "at the stages propagation, carving, candidates, front and alpha"},
      {{"render", "circle.xy", "--wireframe", "-o", "x.png"}, "this picture has none"},
      {{"render", "sphere.xyz", "--stage", "delaunay", "--smooth", "-o", "x.png"},
       "this picture has none"},
      {{"render", "sphere.xyz", "--stage", "voronoi", "--ball-every", "5", "-o", "x.png"},
       "draws none"},
      {{"render", "sphere.xyz", "--stage", "voronoi", "--ball-limit", "5", "-o", "x.png"},
       "draws none"},
      {{"render", "sphere.xyz", "--stage", "poles", "--polar-balls", "--ball-opacity", "0.4",
        "--section", "0.5,0,0", "-o", "x.png"},
       "does not apply to a section"},
      {{"render", "sphere.xyz", "--focus-sample", "3", "--section", "0.5,0,0", "-o", "x.png"},
       "does not apply to a section"},
      {{"render", "circle.xy", "--frames", "10", "-o", "x.png"}, "this is one picture"},
      {{"render", "circle.xy", "--animate", "stages", "--stage", "poles", "-o", "x.webp"},
       "draws every stage in order"},
      {{"render", "circle.xy", "--animate", "stages", "--frames", "10", "-o", "x.webp"},
       "one per stage"},
      {{"render", "circle.xy", "--alpha", "0.3", "-o", "x.png"}, "--alpha is the radius"},
      {{"render", "circle.xy", "--camera", "camera3.json", "-o", "x.png"}, "is a 3D camera", 1},
      {{"render", "--shots", "shots.json", "--size", "300x300"}, "--size does not apply"},
      {{"render", "--shots", "shots.json"}, "no field \"stag\"", 1},
      // The comparisons' and benchmarks' options, by their inputs.
      {{"compare", "sphere.xyz", "--methods", "robust", "--tile", "100x100"}, "there are none"},
      {{"compare", "--example", "star", "--methods", "robust", "--bordered"},
       "applies to point files"},
      {{"compare", "circle.xy", "--methods", "robust", "--reference", "tetrahedron.off"},
       "is 2D points"},
      {{"compare", "sphere.xyz", "--methods", "nn-crust"},
       "nn-crust reconstructs curves (2D points) only"},
      {{"bench", "sphere.xyz", "--methods", "nn-crust"},
       "nn-crust reconstructs curves (2D points) only"},
      {{"bench", "--example", "star", "--merge-duplicates"}, "applies to point files"},
      {{"bench", "circle.xy", "--torus", "-5"}, "'-5' is not a whole number from 1"},
      {{"bench", "circle.xy", "--json", "out.txt"}, "must end in .json"},
      {{"bench", "--render", "100", "--json", "r.json"}, "--json writes the rows"},
      {{"figures", "--only", "fig01", "--size", "100x100abc", "--out", "f"},
       "--size: the size must be WIDTHxHEIGHT"},
  };
  for (const auto& refusal : refusals) {
    std::string command;
    for (const auto& argument : refusal.arguments) command += argument + " ";
    SCOPED_TRACE(command);
    const testing::Command_run run = testing::run_sculpt(folder, refusal.arguments);
    EXPECT_EQ(run.exit_code, refusal.exit_code) << run.err;
    EXPECT_EQ(testing::lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(refusal.says), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run.err;
  }
  // Nothing was written by any of them.
  for (const auto& name : testing::names_in(folder)) {
    EXPECT_TRUE(name == "circle.xy" || name == "sphere.xyz" || name == "camera3.json" ||
                name == "shots.json" || name == "tetrahedron.off")
        << name;
  }
}

// The same options where they apply are taken.
TEST(Unused_options, WhereTheyApplyTheyAreTaken) {
  const fs::path folder = inputs_folder("taken");
  const std::vector<std::vector<std::string>> accepted = {
      {"reconstruct", "sphere.xyz", "--method", "alpha-shape", "--alpha", "0.9", "-o", "a.ply"},
      {"reconstruct", "sphere.xyz", "--method", "paper", "--rule", "extraction", "-o", "b.ply"},
      {"reconstruct", "sphere.xyz", "--box-factor", "20", "-o", "c.ply"},
      {"reconstruct", "sphere.xyz", "--ascii", "-o", "d.stl"},
      {"render", "--example", "star", "--stage", "propagation", "--step", "5", "-o", "e.png"},
      {"render", "sphere.xyz", "--wireframe", "--smooth", "-o", "f.png"},
      {"render", "sphere.xyz", "--stage", "poles", "--polar-balls", "--ball-every", "5", "-o",
       "g.png"},
      {"render", "sphere.xyz", "--stage", "solid", "--polar-balls", "--ball-limit", "20",
       "--section", "0.5,30,60", "-o", "g2.png"},
      {"render", "sphere.xyz", "--stage", "poles", "--polar-balls", "--ball-limit", "0",
       "--ball-opacity", "0.4", "-o", "g3.png"},
      {"render", "circle.xy", "--animate", "stages", "--frame-ms", "500", "-o", "h.webp"},
      // The box of DT(S ∪ BBV) drawn, whatever the method; the edges alone; the paper's rule
      // where robust inserts poles as the paper does.
      {"render", "circle.xy", "--method", "nn-crust", "--stage", "delaunay", "--box-factor", "2",
       "-o", "i.png"},
      {"render", "sphere.xyz", "--method", "alpha-shape", "--stage", "delaunay", "--box-factor",
       "3", "-o", "j.png"},
      {"render", "sphere.xyz", "--wireframe", "--layers", "wireframe,samples", "-o", "k.png"},
      {"reconstruct", "--example", "saddle", "--rule", "skin", "-o", "l.ply"},
      {"reconstruct", "sphere.xyz", "--method", "paper", "--bordered", "--seed-sample", "3", "-o",
       "m.ply"},
  };
  for (const auto& arguments : accepted) {
    std::string command;
    for (const auto& argument : arguments) command += argument + " ";
    SCOPED_TRACE(command);
    const testing::Command_run run = testing::run_sculpt(folder, arguments);
    EXPECT_EQ(run.exit_code, 0) << run.err;
  }
}

}  // namespace
}  // namespace sculpt
