// SPDX-License-Identifier: GPL-3.0-or-later
// The `sculpt` command as a user runs it: outputs, statistics, and one clear line and a
// non-zero exit on bad input, with no output file left behind.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_command.hpp"
#include "file_support.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

using testing::Command_result;
using testing::output_path;
using testing::read_file;
using testing::run_sculpt;
using testing::write_file;

TEST(Cli, ReconstructsAnExampleWithSolidAndStatistics) {
  const auto surface = output_path("torus.stl"), solid = output_path("torus.vtu"),
             stats = output_path("torus.json");
  const Command_result run = run_sculpt("reconstruct --method paper --example torus -o " + surface +
                                        " --solid " + solid + " --stats " + stats);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("verdict: closed 2-manifold of genus 1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("conflicts"), std::string::npos);
  EXPECT_NE(run.out.find("propagation"), std::string::npos);
  const auto json = nlohmann::json::parse(read_file(stats));
  EXPECT_EQ(json["dimension"], 3);
  EXPECT_EQ(json["method"], "paper");
  EXPECT_EQ(json["manifold"], true);
  EXPECT_EQ(json["euler_characteristic"], 0);
  EXPECT_EQ(json["boundary_ridges"], 0);
  EXPECT_EQ(json["stages"].size(), 9u);
  EXPECT_EQ(std::filesystem::file_size(surface), 84u + 50u * json["facets"].get<std::size_t>());
  EXPECT_TRUE(std::filesystem::exists(solid));
}

TEST(Cli, DimensionFollowsTheInput) {
  std::string points;
  for (int i = 0; i < 40; ++i) {
    const double a = 2 * 3.14159265358979 * i / 40;
    points += "p 0 " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + "\n";
  }
  const auto input = write_file("planar.pts", points);
  // Three columns, one constant: a surface cannot be made, and the message says --dim 2.
  const Command_result refused =
      run_sculpt("reconstruct " + input + " -o " + output_path("planar.stl"));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("--dim 2"), std::string::npos) << refused.err;
  const auto curve = output_path("planar.svg");
  const Command_result run = run_sculpt("reconstruct " + input + " --dim 2 -q -o " + curve);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty()) << "--quiet prints nothing";
  EXPECT_NE(read_file(curve).find("<path"), std::string::npos);
}

TEST(Cli, BadInputGivesOneLineAndNoOutput) {
  const std::pair<std::string, std::string> bad[] = {
      {"missing.xyz", ""},
      {"malformed.xyz", "1 2 3\n4 x 6\n0 0 1\n1 1 1\n"},
      {"truncated.xyz", "10\n1 2 3\n4 5 6\n"},
      {"garbage.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 9\n"
       "property double x\nend_header\n\x01\x02"},
      {"nan.xyz", "0 0 0\n1 0 0\n0 1 0\nnan 0 1\n"},
      {"few.xyz", "0 0 0\n1 0 0\n0 1 0\n"},
      {"coplanar.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 3 0\n"},
      {"collinear.xy", "0 0\n1 1\n2 2\n"},
      {"duplicates.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0\n"},
  };
  for (const auto& [name, content] : bad) {
    const std::string input = content.empty() ? output_path(name) : write_file(name, content);
    const auto output =
        output_path(name + (name.find(".xy") == name.size() - 3 ? ".out.svg" : ".out.stl"));
    const Command_result run = run_sculpt("reconstruct " + input + " -o " + output);
    EXPECT_EQ(run.exit_code, 1) << name;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << name << ": " << run.err;
    EXPECT_EQ(run.err.rfind("sculpt: error: ", 0), 0u) << name << ": " << run.err;
    EXPECT_FALSE(std::filesystem::exists(output)) << name;
  }
}

TEST(Cli, VerdictAndRequireManifold) {
  // A sphere with one sample at its centre: the paper method leaves that sample off the
  // surface, and says so; --require-manifold turns that into exit code 3, the output written.
  std::string points;
  for (const auto& p : shapes::sphere(300)) points += fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  points += "0 0 0.01\n";
  const auto input = write_file("sphere-and-centre.xyz", points);
  const auto output = output_path("sphere-and-centre.stl");
  const Command_result plain = run_sculpt("reconstruct --method paper " + input + " -o " + output);
  EXPECT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("verdict: NOT a closed 2-manifold: 1 sample not on it"),
            std::string::npos)
      << plain.out;
  const Command_result quiet =
      run_sculpt("reconstruct -q --method paper " + input + " -o " + output);
  EXPECT_NE(quiet.err.find("NOT a closed 2-manifold"), std::string::npos) << "never silent";
  std::filesystem::remove(output);
  const Command_result strict =
      run_sculpt("reconstruct --require-manifold --method paper " + input + " -o " + output);
  EXPECT_EQ(strict.exit_code, 3);
  EXPECT_TRUE(std::filesystem::exists(output));
  // The robust method brings the sample onto the surface.
  const Command_result robust =
      run_sculpt("reconstruct --require-manifold " + input + " -o " + output);
  EXPECT_EQ(robust.exit_code, 0) << robust.out;
  EXPECT_NE(robust.out.find("method robust"), std::string::npos);
  EXPECT_NE(robust.out.find("verdict: closed 2-manifold"), std::string::npos) << robust.out;
}

TEST(Cli, AFileIsReconstructedAsTheKindItsSamplesShow) {
  // Half a sphere in a file, nothing said about its kind: it comes back with its opening, and
  // the report says the kind was chosen; --closed caps it.
  std::string points;
  for (const auto& p : shapes::hemisphere(1500)) {
    points += fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  }
  const auto input = write_file("half-sphere.xyz", points);
  const auto output = output_path("half-sphere.stl");
  const Command_result chosen = run_sculpt("reconstruct " + input + " -o " + output);
  EXPECT_EQ(chosen.exit_code, 0) << chosen.err;
  EXPECT_NE(chosen.out.find("bordered, method robust"), std::string::npos) << chosen.out;
  EXPECT_NE(chosen.out.find("kind (chosen automatically)"), std::string::npos) << chosen.out;
  EXPECT_NE(chosen.out.find("verdict: bordered 2-manifold with 1 border loop"), std::string::npos)
      << chosen.out;
  const Command_result closed = run_sculpt("reconstruct --closed " + input + " -o " + output);
  EXPECT_NE(closed.out.find("verdict: closed 2-manifold"), std::string::npos) << closed.out;
  EXPECT_EQ(closed.out.find("chosen automatically"), std::string::npos);
  // compare (and bench) are told the kind the same way.
  const Command_result compared = run_sculpt("compare " + input + " --methods robust");
  EXPECT_EQ(compared.exit_code, 0) << compared.err;
  EXPECT_NE(compared.out.find("| bordered 2-manifold with 1 border loop |"), std::string::npos)
      << compared.out;
  const Command_result compared_closed =
      run_sculpt("compare " + input + " --closed --methods robust");
  EXPECT_EQ(compared_closed.exit_code, 0) << compared_closed.err;
  EXPECT_NE(compared_closed.out.find("| closed 2-manifold of genus 0 |"), std::string::npos)
      << compared_closed.out;
  const Command_result both = run_sculpt("compare " + input + " --closed --bordered");
  EXPECT_EQ(both.exit_code, 2) << both.err;
}

TEST(Cli, AllOutputsOrNone) {
  // The solid's folder is missing: nothing is written, not even the surface, and one line says why.
  const auto surface = output_path("all-or-none.stl");
  const Command_result run = run_sculpt("reconstruct --example sphere -o " + surface + " --solid " +
                                        output_path("no-such-folder") + "/s.vtu");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(surface));
  EXPECT_NE(run.err.find("no folder"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1);
  // A TetGen solid is two files, written with the others.
  const auto node = output_path("all-or-none.node");
  const Command_result ok =
      run_sculpt("reconstruct -q --example sphere -o " + surface + " --solid " + node +
                 " --stats " + output_path("all-or-none.json"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(surface));
  EXPECT_TRUE(std::filesystem::exists(std::string(SCULPT_TEST_OUTPUT) + "/all-or-none.ele"));
  EXPECT_TRUE(std::filesystem::exists(std::string(SCULPT_TEST_OUTPUT) + "/all-or-none.json"));
}

TEST(Cli, UnknownMethodIsRefused) {
  const Command_result run =
      run_sculpt("reconstruct --method no-such-method --example star -o " + output_path("x.svg"));
  EXPECT_NE(run.exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(output_path("x.svg")));
}

TEST(Cli, ThePeersByNameAndOneLineWhereTheyDoNotApply) {
  for (const char* method : {"crust", "cocone", "advancing-front"}) {
    const auto surface = output_path(std::string("torus-") + method + ".off");
    const Command_result run = run_sculpt(std::string("reconstruct --require-manifold --method ") +
                                          method + " --example torus -o " + surface);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("closed 2-manifold of genus 1"), std::string::npos) << run.out;
    if (std::string(method) != "advancing-front") {
      EXPECT_NE(run.out.find("candidates / pruned"), std::string::npos) << run.out;
    }
    EXPECT_TRUE(std::filesystem::exists(surface));
  }
  const Command_result curve =
      run_sculpt("reconstruct --method cocone --example star -o " + output_path("cocone.svg"));
  EXPECT_EQ(curve.exit_code, 1);
  EXPECT_NE(curve.err.find("surfaces (3D points) only"), std::string::npos) << curve.err;
  EXPECT_EQ(std::count(curve.err.begin(), curve.err.end(), '\n'), 1) << curve.err;
  EXPECT_FALSE(std::filesystem::exists(output_path("cocone.svg")));
}

TEST(Cli, MergeDuplicatesOnRequest) {
  const auto input =
      write_file("scan-with-repeats.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0\n1 1 1\n");
  const auto output = output_path("scan-with-repeats.off");
  const Command_result refused = run_sculpt("reconstruct " + input + " -o " + output);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("--merge-duplicates"), std::string::npos) << refused.err;
  const Command_result merged =
      run_sculpt("reconstruct " + input + " --merge-duplicates -o " + output);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(merged.out.find("1 duplicate points merged"), std::string::npos) << merged.out;
  EXPECT_NE(read_file(output).find("\n5 "), std::string::npos) << "five distinct vertices";
}

TEST(Cli, UnknownOutputFormatFailsBeforeWork) {
  const Command_result run =
      run_sculpt("reconstruct --example sphere -o " + output_path("sphere.xyz"));
  EXPECT_EQ(run.exit_code, 2) << "an output format Sculpt cannot write is bad usage";
  EXPECT_NE(run.err.find("known: .stl"), std::string::npos) << run.err;
}

// libOSMesa brings libLLVM (~50 MiB resident, tens of ms to load): only drawing may load it.
TEST(Cli, OnlyRenderingLoadsTheRenderer) {
  setenv("LD_DEBUG", "libs", 1);  // the dynamic loader lists every library it opens
  const Command_result reconstruct =
      run_sculpt("reconstruct --example star -q -o " + output_path("no-renderer.svg"));
  const Command_result render = run_sculpt("render --example star --stage poles --size 64x64 -o " +
                                           output_path("renderer.png"));
  unsetenv("LD_DEBUG");
  EXPECT_EQ(reconstruct.exit_code, 0);
  EXPECT_NE(reconstruct.err.find("libc.so"), std::string::npos) << "LD_DEBUG listed nothing";
  EXPECT_EQ(reconstruct.err.find("OSMesa"), std::string::npos);
  EXPECT_EQ(reconstruct.err.find("LLVM"), std::string::npos);
  EXPECT_EQ(render.exit_code, 0) << render.err.substr(
      render.err.size() - std::min<std::size_t>(500, render.err.size()));
  EXPECT_NE(render.err.find("libsculpt_osmesa.so"), std::string::npos);
  EXPECT_NE(render.err.find("libOSMesa"), std::string::npos);
}

TEST(Cli, ABorderedExampleIsReconstructedBorderedWithoutBeingTold) {
  const Command_result run =
      run_sculpt("reconstruct --example saddle --require-manifold -o " + output_path("saddle.ply"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("verdict: bordered 2-manifold with 1 border loop"), std::string::npos)
      << run.out;
}

TEST(Cli, RenderMergesRepeatedPointsWhenTold) {
  std::string text;
  for (const auto& p : shapes::sphere(300)) text += fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  text += text.substr(0, text.find('\n') + 1);  // the first point again
  const std::string scan = testing::write_file("render-repeated.xyz", text);
  const std::string picture = output_path("render-repeated.png");
  const Command_result refused = run_sculpt("render " + scan + " --stage samples -o " + picture);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("--merge-duplicates"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(picture));
  const Command_result merged =
      run_sculpt("render " + scan + " --merge-duplicates --stage samples -o " + picture);
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_TRUE(std::filesystem::exists(picture));
}

// The frames of an animated WebP: its ANMF chunks, read off the RIFF container.
std::size_t webp_frames(const std::string& bytes) {
  if (bytes.size() < 12 || bytes.compare(0, 4, "RIFF") != 0 || bytes.compare(8, 4, "WEBP") != 0)
    return 0;
  std::size_t frames = 0;
  for (std::size_t at = 12; at + 8 <= bytes.size();) {
    const auto byte = [&](std::size_t i) { return std::size_t(std::uint8_t(bytes[at + 4 + i])); };
    const std::size_t size = byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
    frames += bytes.compare(at, 4, "ANMF") == 0;
    at += 8 + size + (size & 1);
  }
  return frames;
}

// `sculpt render --animate`: the replay of the labelling or a sweep of the stages as an
// animated WebP or GIF; a method without a replay, or a PNG name, is one line and no file.
TEST(Cli, RenderAnimatesTheReplayAndTheStages) {
  const std::string replay = output_path("replay.webp"), stages = output_path("stages.webp");
  ASSERT_EQ(
      run_sculpt("render --example star --animate replay --frames 12 --size 200x150 -o " + replay)
          .exit_code,
      0);
  // (The encoder merges a picture into the one before when nothing on screen changed.)
  EXPECT_GE(webp_frames(read_file(replay)), 10u);
  EXPECT_LE(webp_frames(read_file(replay)), 12u);
  ASSERT_EQ(run_sculpt("render --example blob --method crust --animate stages --size 200x150 -o " +
                       stages)
                .exit_code,
            0);
  EXPECT_EQ(webp_frames(read_file(stages)), 5u);  // the crust's five 2D stages
  // For slide software: a looping GIF (its frames are checked in tests/animation_test.cpp).
  const std::string gif = output_path("stages.gif");
  ASSERT_EQ(
      run_sculpt("render --example blob --method crust --animate stages --size 200x150 -o " + gif)
          .exit_code,
      0);
  const std::string gif_bytes = read_file(gif);
  EXPECT_EQ(gif_bytes.substr(0, 6), "GIF89a");
  EXPECT_NE(gif_bytes.find("NETSCAPE2.0"), std::string::npos);
  EXPECT_EQ(gif_bytes.back(), ';');  // the trailer
  // The carving replays too, in 2D and 3D, and so do the peers that grow.
  for (const std::string& carving :
       {std::string("render --example star --method paper --stage carving"),
        std::string("render --example bumpy --method robust --stage carving"),
        std::string("render --example bumpy --method advancing-front --stage front"),
        std::string("render --example bumpy --method alpha-shape --stage alpha")}) {
    const std::string film = output_path("carving.webp");
    ASSERT_EQ(
        run_sculpt(carving + " --animate replay --frames 6 --size 200x150 -o " + film).exit_code, 0)
        << carving;
    EXPECT_GE(webp_frames(read_file(film)), 4u) << carving;
  }
  const std::string refused = output_path("refused.webp");
  const Command_result no_replay =
      run_sculpt("render --example blob --method crust --animate replay -o " + refused);
  EXPECT_EQ(no_replay.exit_code, 1);
  EXPECT_NE(no_replay.err.find("no replay"), std::string::npos) << no_replay.err;
  EXPECT_FALSE(std::filesystem::exists(refused));
  const Command_result png =
      run_sculpt("render --example star --animate replay -o " + output_path("a.png"));
  EXPECT_EQ(png.exit_code, 2);
  EXPECT_NE(png.err.find("ends in neither .webp nor .gif"), std::string::npos) << png.err;
}

TEST(Cli, VersionAndHelp) {
  EXPECT_EQ(run_sculpt("--version").exit_code, 0);
  const Command_result help = run_sculpt("reconstruct --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--bordered"), std::string::npos);
  EXPECT_NE(help.out.find("--box-factor"), std::string::npos);
}

// A shots file with a field of the wrong type, or a number out of its range, is refused in one
// line naming the shot, the key and what it takes: not the JSON library's internal error, and
// not a number wrapped into a negative one.
TEST(Cli, ShotFieldsOfTheWrongKindAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"step": 1e300})", R"(shot 1: "step" takes a whole number from -1 to)"},
      {R"({"step": 2.5})", R"(shot 1: "step" takes a whole number)"},
      {R"({"size": 640})", R"(shot 1: "size" takes text in quotes, not 640)"},
      {R"({"layers": "samples"})", R"(shot 1: "layers" takes a list of names in quotes)"},
      {R"({"wireframe": "yes"})", R"(shot 1: "wireframe" takes true or false)"},
      {R"({"ball_every": 0})", R"(shot 1: "ball_every" takes a whole number from 1 to)"},
      {R"(42)", "shot 1 is not a JSON object"}};
  for (const auto& [fields, says] : cases) {
    SCOPED_TRACE(fields);
    std::string shot = fields;
    if (shot.front() == '{') {
      shot = R"({"example": "star", "output": ")" + output_path("never.png") + "\", " +
             fields.substr(1);
    }
    const auto file = write_file("typed-shots.json", R"({"shots": [)" + shot + "]}");
    const Command_result run = run_sculpt("render --shots " + file);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(run.err.find("json.exception"), std::string::npos) << run.err;
  }
}

// A value with something after it, a flag for another kind of input, or two ways of naming the
// output: each refused in one line, nothing written.
TEST(Cli, WhatDoesNotApplyIsRefused) {
  const auto picture = output_path("refused.png");
  const auto shots = write_file("empty-shots.json", R"({"shots": []})");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"render --example star -o " + picture + " --size 64x64garbage", "WIDTHxHEIGHT"},
      {"render --example star -o " + picture + " --clip 0.5,0,90", "2D curve"},
      {"render --example star -o " + picture + " --section 0.5,0,90", "2D curve"},
      {"render --example torus -o " + picture + " --section 0.5,0,90 --clip 0.5,0,90", "not both"},
      {"render --example torus -o " + picture + " --section 0.5,0,90,0.1", "POSITION,AZIMUTH"},
      {"render --example torus -o " + picture + " --polar-balls --ball-opacity 1.5",
       "ball_opacity"},
      {"reconstruct --example star -o " + output_path("s.svg") + " --seed-sample -2", "-2"},
      {"render --shots " + shots + " -o " + picture, "excludes"}};
  for (const auto& [arguments, says] : cases) {
    SCOPED_TRACE(arguments);
    const Command_result run = run_sculpt(arguments);
    EXPECT_NE(run.exit_code, 0);
    EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(picture));
  }
}

// A mistyped option is named, with the nearest one, even when its value would otherwise be
// taken for an input (CLI11 then blamed the input: "input excludes --example").
TEST(Cli, AMistypedOptionIsNamedWithTheNearestOne) {
  const Command_result typo =
      run_sculpt("render --example torus --secton 0.5,0,0 -o " + output_path("typo.png"));
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("no option '--secton' (did you mean '--section'?)"), std::string::npos)
      << typo.err;
  EXPECT_EQ(std::count(typo.err.begin(), typo.err.end(), '\n'), 1) << typo.err;
  EXPECT_FALSE(std::filesystem::exists(output_path("typo.png")));
}

TEST(Cli, AMistypedCommandIsNamedWithTheNearestOne) {
  const Command_result typo = run_sculpt("reconstrut --example torus");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("no command 'reconstrut' (did you mean 'reconstruct'?)"),
            std::string::npos)
      << typo.err;
  EXPECT_NE(typo.err.find("the commands are reconstruct, examples"), std::string::npos);
  // Nothing near: the commands are listed, no guess.
  const Command_result far = run_sculpt("sculptify");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  // A file given first: the command it was most likely meant for.
  const std::string input = write_file("cli-first-word.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  const Command_result file = run_sculpt(input);
  EXPECT_NE(file.err.find("did you mean 'sculpt reconstruct " + input + "'?"), std::string::npos)
      << file.err;
}

}  // namespace
}  // namespace sculpt
