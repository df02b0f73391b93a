// SPDX-License-Identifier: GPL-3.0-or-later
// Outputs as safe as the readers, through the `sculpt` command: an output never replaces an
// input, whatever name reaches it; every destination is checked before any work and a run's
// outputs appear together or not at all; a read-only file is not replaced; no signal, file-size
// limit or kill leaves a temporary that nothing removes; a report that cannot be written is a
// failure.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "file_support.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "sculpt_process.hpp"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  return testing::fresh_folder("output-safety/" + name);
}

using testing::Command_run;
using testing::lines;
using testing::names_in;
using testing::run_sculpt;

TEST(Output_safety, AnOutputNeverReplacesAnInputWhateverItsName) {
  const fs::path folder = fresh_folder("same-file");
  fs::create_directories(folder / "sub");
  const std::string points = testing::sphere_points_text(300);
  testing::write_file("output-safety/same-file/in.xyz", points);
  fs::create_symlink("in.xyz", folder / "link.xyz");
  fs::create_hard_link(folder / "in.xyz", folder / "hard.xyz");
  // Each names the input (or a name of it) as an output, in some other spelling.
  const std::vector<std::vector<std::string>> runs = {
      {"reconstruct", "in.xyz", "-o", "in.xyz"},
      {"reconstruct", "in.xyz", "-o", "sub/../in.xyz"},
      {"reconstruct", "in.xyz", "-o", (folder / "in.xyz").string()},
      {"reconstruct", "link.xyz", "-o", "in.xyz"},
      {"reconstruct", "in.xyz", "-o", "link.xyz"},
      {"reconstruct", "in.xyz", "-o", "hard.xyz"},
      {"reconstruct", "in.xyz", "-o", "out.off", "--solid", "in.xyz"},
      {"render", "in.xyz", "-o", "out.png", "--save-camera", "in.xyz"},
      {"render", "in.xyz", "-o", "out.png", "--save-camera", "link.xyz"},
  };
  for (const auto& arguments : runs) {
    SCOPED_TRACE(fmt::format("sculpt {}", fmt::join(arguments, " ")));
    const Command_run run = run_sculpt(folder, arguments);
    EXPECT_NE(run.exit_code, 0) << run.err;
    EXPECT_EQ(lines(run.err), 1) << run.err;
    EXPECT_TRUE(run.err.find("never replaces an input") != std::string::npos ||
                run.err.find("cannot write") != std::string::npos)
        << run.err;
    EXPECT_EQ(testing::read_file((folder / "in.xyz").string()), points) << "the input is intact";
    EXPECT_EQ(names_in(folder), (std::vector<std::string>{"hard.xyz", "in.xyz", "link.xyz", "sub"}))
        << "nothing written";
  }
  // The refusal comes before the work, and names the path as the user gave it.
  const Command_run named =
      run_sculpt(folder, {"reconstruct", "in.xyz", "-o", "sub/../in.xyz", "--ascii"});
  EXPECT_NE(named.err.find("'sub/../in.xyz'"), std::string::npos) << named.err;
}

TEST(Output_safety, OutputsOfOneRunAreNotOneFileAndNotAFolder) {
  const fs::path folder = fresh_folder("destinations");
  testing::write_file("output-safety/destinations/in.xyz", testing::sphere_points_text(300));
  fs::create_directories(folder / "taken.json");
  fs::create_directories(folder / "sub");
  ::mkfifo((folder / "pipe.off").c_str(), 0644);
  const std::vector<std::vector<std::string>> runs = {
      {"reconstruct", "in.xyz", "-o", "out.off", "--stats", "taken.json"},
      {"reconstruct", "in.xyz", "-o", "pipe.off"},
      {"reconstruct", "in.xyz", "-o", "out.node", "--solid", "out.ele"},
      {"reconstruct", "in.xyz", "-o", "out.off", "--solid", "sub/../out.off"},
  };
  for (const auto& arguments : runs) {
    SCOPED_TRACE(fmt::format("sculpt {}", fmt::join(arguments, " ")));
    const Command_run run = run_sculpt(folder, arguments);
    EXPECT_NE(run.exit_code, 0) << run.err;
    EXPECT_EQ(lines(run.err), 1) << run.err;
    EXPECT_EQ(names_in(folder),
              (std::vector<std::string>{"in.xyz", "pipe.off", "sub", "taken.json"}));
  }
}

// A file made read-only is not replaced by an output renamed over it (root, who may write to
// any file, included): the run is refused before any work, the file intact.
TEST(Output_safety, AReadOnlyFileIsNotReplaced) {
  const fs::path folder = fresh_folder("read-only");
  testing::write_file("output-safety/read-only/in.xyz", testing::sphere_points_text(300));
  testing::write_file("output-safety/read-only/kept.off", "OFF\n0 0 0\n");
  fs::permissions(folder / "kept.off", fs::perms::owner_read | fs::perms::group_read |
                                            fs::perms::others_read);
  const Command_run run = run_sculpt(folder, {"reconstruct", "in.xyz", "-o", "kept.off"});
  EXPECT_NE(run.exit_code, 0) << run.err;
  EXPECT_EQ(lines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("read-only"), std::string::npos) << run.err;
  EXPECT_EQ(testing::read_file((folder / "kept.off").string()), "OFF\n0 0 0\n");
  EXPECT_EQ(names_in(folder), (std::vector<std::string>{"in.xyz", "kept.off"}));
  fs::permissions(folder / "kept.off", fs::perms::owner_write, fs::perm_options::add);
  EXPECT_EQ(run_sculpt(folder, {"reconstruct", "in.xyz", "-o", "kept.off"}).exit_code, 0);
}

TEST(Output_safety, ShotsAreWrittenAllOrNone) {
  // The second shot cannot be written: the first is not left behind, and nothing is drawn.
  const fs::path folder = fresh_folder("shots");
  fs::create_directories(folder / "taken.png");
  testing::write_file("output-safety/shots/shots.json", R"({"shots": [
      {"example": "star", "stage": "voronoi", "size": "64x64", "output": "first.png"},
      {"example": "star", "stage": "poles", "size": "64x64", "output": "taken.png"}]})");
  const Command_run run = run_sculpt(folder, {"render", "--shots", "shots.json"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(lines(run.err), 1) << run.err;
  EXPECT_EQ(names_in(folder), (std::vector<std::string>{"shots.json", "taken.png"}));
  // A picture and its camera: both, or neither.
  const Command_run camera = run_sculpt(
      folder, {"render", "--example", "star", "-o", "star.png", "--save-camera", "taken.png"});
  EXPECT_EQ(camera.exit_code, 1) << camera.err;
  EXPECT_EQ(names_in(folder), (std::vector<std::string>{"shots.json", "taken.png"}));
}

// A run ended by any signal that a handler can catch leaves its outputs complete or absent,
// and never a temporary.
TEST(Output_safety, NoSignalLeavesATemporary) {
  const fs::path folder = fresh_folder("signals");
  testing::write_file("output-safety/signals/in.xyz", testing::sphere_points_text(30000));
  for (const int signal : {SIGHUP, SIGQUIT, SIGXCPU, SIGALRM, SIGUSR1, SIGUSR2, SIGPIPE, SIGTERM}) {
    for (const int milliseconds : {100, 600, 1200}) {
      SCOPED_TRACE(
          fmt::format("signal {} ({}) after {} ms", signal, strsignal(signal), milliseconds));
      for (const auto& name : names_in(folder))
        if (name != "in.xyz") fs::remove_all(folder / name);
      const Command_run run = run_sculpt(
          folder,
          {"reconstruct", "in.xyz", "-o", "s.stl", "--solid", "s.node", "--stats", "s.json", "-q"},
          {signal, milliseconds, -1, {}});
      const auto names = names_in(folder);
      if (names.size() > 1) {
        EXPECT_EQ(names,
                  (std::vector<std::string>{"in.xyz", "s.ele", "s.json", "s.node", "s.stl"}));
      }
      if (run.exit_code == -1) {
        EXPECT_EQ(run.signal, signal);
      }
    }
  }
}

TEST(Output_safety, AFileSizeLimitFailsTheRunCleanly) {
  // SIGXFSZ would kill the run mid-write; it is ignored, and the write fails in one line.
  const fs::path folder = fresh_folder("file-size");
  testing::write_file("output-safety/file-size/in.xyz", testing::sphere_points_text(3000));
  const Command_run run =
      run_sculpt(folder, {"reconstruct", "in.xyz", "-o", "s.stl", "-q"}, {0, 0, 64 * 1024, {}});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(lines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("'s.stl'"), std::string::npos) << "the user's name: " << run.err;
  EXPECT_NE(run.err.find("file-size limit"), std::string::npos) << run.err;
  EXPECT_EQ(names_in(folder), std::vector<std::string>{"in.xyz"});
}

TEST(Output_safety, TheNextRunRemovesWhatAKilledRunLeft) {
  // SIGKILL runs no handler: the temporary stays until a run writes the same output.
  const fs::path folder = fresh_folder("killed");
  testing::write_file("output-safety/killed/in.xyz", testing::sphere_points_text(3000));
  // A dead process's temporaries (a process id that no process has now), and a live one's.
  const pid_t dead = [] {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return child;
  }();
  testing::write_file(fmt::format("output-safety/killed/.s.sculpt-{}.node", dead), "half");
  testing::write_file(fmt::format("output-safety/killed/.s.sculpt-{}.ele", dead), "half");
  testing::write_file(fmt::format("output-safety/killed/.s.sculpt-{}.node", ::getpid()), "live");
  const Command_run run =
      run_sculpt(folder, {"reconstruct", "in.xyz", "-o", "s.off", "--solid", "s.node", "-q"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(names_in(folder),
            (std::vector<std::string>{fmt::format(".s.sculpt-{}.node", ::getpid()), "in.xyz",
                                      "s.ele", "s.node", "s.off"}));
}

TEST(Output_safety, AnyLegalNameCanBeAnOutput) {
  // 255 bytes, the longest name a folder holds: the temporary's name is shortened, not refused.
  const fs::path folder = fresh_folder("long-name");
  testing::write_file("output-safety/long-name/in.xyz", testing::sphere_points_text(300));
  const std::string name = std::string(251, 'n') + ".off";
  const Command_run run = run_sculpt(folder, {"reconstruct", "in.xyz", "-o", name, "-q"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(names_in(folder), (std::vector<std::string>{"in.xyz", name}));
}

TEST(Output_safety, AReportThatCannotBeWrittenIsAFailure) {
  const fs::path folder = fresh_folder("full-stdout");
  const std::string command =
      fmt::format("cd {} && {} reconstruct --example star -o s.svg >/dev/full 2>err",
                  folder.string(), SCULPT_EXECUTABLE);
  const int status = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(testing::read_file((folder / "err").string()).find("standard output"),
            std::string::npos);
}

// The figures are one set of outputs in one folder: a run that fails makes no folder...
TEST(Output_safety, AFailedGalleryLeavesNoFolder) {
  const fs::path folder = fresh_folder("gallery-failed");
  // A file-size limit too small for a picture: the disk full, as far as the run can tell.
  const Command_run run =
      run_sculpt(folder, {"figures", "--only", "fig01", "--size", "120x90", "--out", "new/gallery"},
                 {0, 0, 2048, {}});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("file-size limit"), std::string::npos) << run.err;
  EXPECT_EQ(names_in(folder), std::vector<std::string>{}) << "no folder, no temporary";
}

// ... and leaves a folder that was there as it was; every destination is checked first.
TEST(Output_safety, AGalleryIsWrittenWholeOrNotAtAll) {
  const fs::path folder = fresh_folder("gallery-set");
  const fs::path gallery = folder / "gallery";
  fs::create_directories(gallery / "figures.json");  // in the way of an output
  testing::write_file("output-safety/gallery-set/gallery/notes.txt", "mine");
  const std::vector<std::string> arguments = {"figures", "--only", "fig01",  "--size",
                                              "120x90",  "--out",  "gallery"};
  const Command_run refused = run_sculpt(folder, arguments);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_EQ(lines(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("figures.json': it is a folder"), std::string::npos) << refused.err;
  EXPECT_EQ(refused.err.find("sculpt figures: fig01"), std::string::npos) << "before any work";
  EXPECT_EQ(names_in(gallery), (std::vector<std::string>{"figures.json", "notes.txt"}));

  fs::remove(gallery / "figures.json");
  const Command_run written = run_sculpt(folder, arguments);
  EXPECT_EQ(written.exit_code, 0) << written.err;
  const auto names = names_in(gallery);
  EXPECT_EQ(std::count_if(names.begin(), names.end(),
                          [](const std::string& name) { return name.rfind("fig01", 0) == 0; }),
            2);  // fig01a, fig01b
  for (const char* expected : {"figures.json", "notes.txt"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  // One figure leaves the tables of the whole gallery alone (none here to leave).
  for (const char* whole : {"table1.md", "table2.md", "README.md"})
    EXPECT_EQ(std::find(names.begin(), names.end(), whole), names.end()) << whole;
  EXPECT_EQ(std::count_if(names.begin(), names.end(),
                          [](const std::string& name) { return name.front() == '.'; }),
            0);
  EXPECT_EQ(testing::read_file((gallery / "notes.txt").string()), "mine");
}

// The library's own check, as the viewer and Python use it: a file read earlier in the process.
TEST(Output_safety, AFileReadEarlierInTheProcessIsNotReplaced) {
  const fs::path folder = fresh_folder("remembered");
  const std::string input = testing::write_file("output-safety/remembered/read.xyz", "0 0 0\n");
  EXPECT_NO_THROW(io::check_destination((folder / "read.xyz").string()));
  io::remember_input(input);
  EXPECT_THROW(io::check_destination((folder / "read.xyz").string()), io::Error);
  EXPECT_THROW(io::check_destination((folder / "." / "read.xyz").string()), io::Error);
  EXPECT_NO_THROW(io::check_destination((folder / "other.xyz").string()));
  EXPECT_THROW(io::check_destinations({(folder / "a.off").string(), (folder / "./a.off").string()}),
               io::Error);
}

}  // namespace
}  // namespace sculpt
