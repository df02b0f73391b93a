// A shot: one picture of one stage of one input, as `sculpt render`, the viewer's "save
// picture", the paper's figures and the viewer's tour of them describe it. Plain data.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt::frontend {

struct Shot {
  std::string input, example;
  bool bordered = false;
  int dimension = 0;
  std::string stage = "surface";
  long step = -1;
  int focus_sample = -1, focus_pole = -1;
  std::string method = to_string(Options{}.method);
  double box_factor = Options{}.box_factor;
  double alpha = Options{}.alpha;
  std::string rule = "auto";
  std::vector<std::string> layers;
  std::string camera_file, save_camera;
  std::string size = "800x800";
  bool wireframe = false, smooth = false, no_legend = false;
  double zoom = 1.0;               // applied to the fitted camera (< 1 zooms in)
  int ball_every = 1;              // polar balls of every k-th pole only
  double yaw = 0.6, pitch = 0.35;  // 3D: direction the fitted camera looks from (radians)
  std::string title;               // replaces the stage's title, when given
  std::string output;
};

}  // namespace sculpt::frontend
