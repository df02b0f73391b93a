// `sculpt render`: pictures of any stage, headless (OSMesa), one shot or a list of shots in
// one process.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sculpt::cli {

struct Shot {
  std::string input, example;
  bool bordered = false;
  int dimension = 0;
  std::string stage = "surface";
  long step = -1;
  int focus_sample = -1, focus_pole = -1;
  double box_factor = 5.0;
  std::string rule = "auto";
  std::vector<std::string> layers;
  std::string camera_file, save_camera;
  std::string size = "800x800";
  bool wireframe = false, smooth = false, no_legend = false;
  std::string output;
};

struct Render_arguments {
  Shot shot;
  std::string shots_file;  // JSON: {"shots": [ {...}, ... ]} with the fields of Shot
};

void add_render_command(CLI::App& app, Render_arguments& args);
int run_render(const Render_arguments& args);

}  // namespace sculpt::cli
