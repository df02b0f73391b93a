// SPDX-License-Identifier: GPL-3.0-or-later
// A shot: one picture of one stage of one input, as `sculpt render`, the viewer's "save
// picture", the paper's figures and the viewer's tour of them describe it. Plain data.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "shapes/shapes.hpp"

namespace sculpt::frontend {

struct Shot {
  std::string input, example;
  // The kind of surface: bordered if asked or if the example is so, unless closed is forced
  // (a lesson on what the closed algorithm does to a sheet); a file's, chosen: kind_of().
  bool bordered = false, closed = false;
  bool merge_duplicates = false;  // drop a file's repeated points instead of refusing it
  int dimension = 0;
  std::string stage = "surface";
  long step = -1;
  int focus_sample = -1, focus_pole = -1;
  std::string method = to_string(Options{}.method);
  double box_factor = Options{}.box_factor;
  double alpha = Options{}.alpha;
  std::string rule = "auto";
  std::string clean = "auto";  // Options::cleaning by name (cleaning_choices)
  std::vector<std::string> layers;
  std::string clip;     // 3D cut-away "POSITION,AZIMUTH,ELEVATION" (scene::Clip); empty: none
  std::string section;  // 3D true section at the plane "POSITION,AZIMUTH,ELEVATION"; empty: none
  std::string camera_file, save_camera;
  std::string size = "800x800";
  bool wireframe = false, smooth = false, no_legend = false;
  double zoom = 1.0;               // applied to the fitted camera (< 1 zooms in)
  int ball_every = 1;              // polar balls of every k-th pole only
  bool polar_balls = false;        // 3D: the polar balls at any stage (every ball_every-th)
  std::string palette = "paper";  // the colour scheme: paper or colour-blind (scene/colours.hpp)
  int ball_limit = 0;              // 3D: at most this many balls of each kind (0: all)
  double ball_opacity = 0.8;       // 3D: of the translucent balls
  bool neighbourhood = false;      // only what lies near the focus sample (scene::Request)
  double yaw = 0.6, pitch = 0.35;  // 3D: direction the fitted camera looks from (radians)
  std::string title;               // replaces the stage's title, when given
  // An animation instead of one picture (an animated WebP): "replay" (the labelling, event by
  // event, in `frames` pictures) or "stages" (the method's stages in order, one picture each),
  // each picture shown `frame_ms` (0: 80 ms a replay's, 1,200 ms a stage's).
  std::string animate;
  int frames = 60;
  int frame_ms = 0;
  std::string output;
};

// The kind an input is reconstructed as: closed or bordered if asked (closed wins: a lesson on
// what the closed algorithm does to a sheet), else an example's own kind, else (a file) the
// default, chosen from the samples. The command line, render, the viewer and the benchmark
// agree through this.
inline Surface_kind input_kind(const shapes::Example* example, bool bordered, bool closed) {
  if (closed) return Surface_kind::closed;
  if (bordered) return Surface_kind::bordered;
  if (example) return example->bordered ? Surface_kind::bordered : Surface_kind::closed;
  return Options{}.kind;
}

inline Surface_kind kind_of(const Shot& shot) {
  return input_kind(shapes::find_example(shot.example), shot.bordered, shot.closed);
}

}  // namespace sculpt::frontend
