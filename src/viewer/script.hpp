// SPDX-License-Identifier: GPL-3.0-or-later
// Scripted runs of the viewer, for tests and demonstrations: one command a line, run in order
// between frames, e.g.
//   example star        open a built-in example (open PATH for a file)
//   kind bordered       the kind what is opened next is reconstructed as (closed, automatic)
//   wait                until the reconstruction has finished and any move to a tour panel
//                       has ended (fail if the reconstruction failed)
//   wait-idle           until no reconstruction runs, whatever its outcome
//   cancel              ask the running reconstruction to stop
//   expect-idle         fail if a reconstruction runs (right after cancel: the cancel was at once)
//   expect-busy         fail unless a reconstruction is running (the UI is not blocked)
//   stage poles         show a stage (next / previous step through them)
//   method crust        reconstruct the loaded input again with another method
//   clean jet           the same with the samples smoothed first (outliers, outliers+jet,
//                       auto: both when noisy; none)
//   compare paper,robust  two to four methods side by side on the points shown, one camera
//                       for all, each with its verdict (wait: until all have come); compare off
//   step 25             a replay: the first 25 labelling events (propagation) or carving steps
//   replay carving 50   show a replay from its start and play it, 50 steps a second (optional;
//                       also propagation, candidates, front, alpha); wait-replay: until it ends
//   clip 0.5 30 60      3D: cut away beyond a plane (position 0..1, azimuth, elevation); clip off
//   section 0.5 0 90    3D: the stage in section at that plane, seen along it; section off
//   pick-sample 10      select a sample (pick-pole N: a pole)
//   explain             print the Explanation panel's paragraph for the stage on screen
//   stats               print the shown reconstruction's statistics, one JSON line
//   edit on             2D: the mouse adds, drags and deletes samples (edit off: it does not)
//   add-point 0.1 0.2   2D: add a sample and reconstruct (move-point K X Y, delete-point K,
//                       stroke SPACING X1 Y1 X2 Y2 ..., undo, save-points a.xy)
//   layer voronoi off   hide (or show) a layer of the stage on screen
//   neighbourhood on    only what lies near the picked sample (pick-sample first)
//   polar-balls 20      3D: draw every 20th pole's polar ball (0 or off: none)
//   camera zoom 0.5     also: camera fit, orbit 30 -10 (degrees), pan 0.2 0 (half heights),
//                       save cam.json, load cam.json
//   follow off          the replay's camera stays put (on: it keeps the pole just labelled in view)
//   present on          presentation mode: no panel, the legend in the picture (off: back)
//   palette colour-blind  colours apart with deuteranopia and protanopia too (paper: the paper's)
//   picture-scale 2     points, lines and the picture's legend twice their size (0.5 to 4)
//   frames 3            draw three frames
//   screenshot a.png    save the window, panels included
//   export b.png 800x600  save a picture through the headless renderer
//   export-animation c.webp 640x480 40  an animated WebP (or c.gif): the replay at a stage that
//                       replays (40 pictures), else the method's stages
//   figure fig06        open a figure of the paper at its first panel
//   panel next          the tour: next, previous, 3 (1-based) or c
//   expect-panel fig06c fail unless that panel is on screen as the figure shows it
//   key pagedown        press a key (pagedown, pageup, ], [, t, escape, right, left, space, ...)
//   animation off       jump to tour panels instead of moving there
//   save-result a.ply   the result: a surface (.ply .obj .stl .off) or curve (.svg .obj)
//   link                print the link (browser) or command line (desktop) of this view
//   message             print the panel's message line
//   figures             print the paper's figures and their panels (JSON)
//   quit
// A command with a missing or malformed argument prints one line and fails the script.
#pragma once

#include <deque>
#include <string>

#include "viewer.hpp"

namespace sculpt::viewer {

class Script {
 public:
  // automatic: run through (tests, demonstrations); lesson: watched by a class, each
  // `screenshot` a pause until resume(), files not written, the comment block right above a
  // command shown as the narration while it runs (examples/lessons).
  enum class Mode { automatic, lesson };
  static Script from_file(const std::string& path);  // throws std::runtime_error
  static Script from_text(const std::string& text, Mode mode = Mode::automatic);
  // A script the command line's options stand for (--frames): its failures say what failed
  // without naming a script the user never wrote.
  static Script from_options(const std::string& text);

  // Runs commands until one needs frames to pass. Returns a screenshot path to save after this
  // frame is drawn, if a command asked for one.
  std::string before_frame(Viewer& viewer);
  // Commands run before the script's own (the first view the command line asks for).
  void run_first(const std::string& commands);
  bool finished() const { return commands_.empty() && frames_to_wait_ == 0 && !paused_; }
  bool failed() const { return failed_; }

  // A lesson: paused at a picture, the narration of the commands running, and the step.
  bool is_lesson() const { return mode_ == Mode::lesson; }
  bool paused() const { return paused_; }
  void resume();
  const std::string& narration() const { return narration_; }
  int step() const { return step_; }         // 1-based
  int steps() const { return pauses_ + 1; }  // the pauses divide the lesson into steps

 private:
  void fail(const std::string& why);  // one line on stderr; the script will exit non-zero

  struct Command {
    std::string line;
    std::string narration;  // the comment block right above it, as one paragraph per blank #
  };
  std::deque<Command> commands_;
  int frames_to_wait_ = 0;
  bool failed_ = false;
  Mode mode_ = Mode::automatic;
  bool from_options_ = false;
  bool paused_ = false;
  int step_ = 1, pauses_ = 0;
  std::string narration_;
};

}  // namespace sculpt::viewer
