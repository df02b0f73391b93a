// SPDX-License-Identifier: GPL-3.0-or-later
// The script's commands that write files (pictures, animations, points, results) or print a
// line on standard output for demonstrations and tests.
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "figures/paper_figures.hpp"
#include "script_line.hpp"

namespace sculpt::viewer {

bool run_output_command(Script_line& line) {
  Viewer& viewer = line.viewer;
  if (line.command == "export") {
    if (!line.needs_argument("a PNG path")) return true;
    const auto size = line.extra.empty() ? std::pair<int, int>(800, 600) : picture_size(line.extra);
    if (!size) {
      line.fail("'" + line.text + "': expected a size WIDTHxHEIGHT, 16 to 8192 pixels each");
      return true;
    }
    line.done(viewer.export_picture(line.argument, size->first, size->second));
  } else if (line.command == "message") {
    // The panel's message line (what was opened, saved or refused), on standard output.
    std::cout << "message: " << viewer.message() << std::endl;
  } else if (line.command == "figures") {
    // The paper's figures and their panels, one JSON line on standard output.
    nlohmann::json all = nlohmann::json::array();
    for (const auto& figure : figures::paper_figures()) {
      nlohmann::json panels = nlohmann::json::array();
      for (std::size_t i = 0; i < figure.images.size(); ++i)
        panels.push_back(figure.id + figure.images[i].suffix);
      all.push_back({{"id", figure.id}, {"panels", panels}});
    }
    std::cout << "figures: " << all.dump() << std::endl;
  } else if (line.command == "explain") {
    // The Explanation panel's paragraph, on standard output: for demos and tests.
    if (!viewer.has_reconstruction()) {
      line.fail("'explain': no reconstruction on screen");
      return true;
    }
    std::cout << "explain " << scene::stage_id(viewer.stage()) << ": " << viewer.explanation()
              << std::endl;
  } else if (line.command == "export-animation") {
    // export-animation PATH.webp|PATH.gif [WIDTHxHEIGHT [FRAMES]]
    if (line.arguments.empty()) {
      line.fail("'export-animation' needs a .webp or .gif path");
      return true;
    }
    const auto size =
        line.arguments.size() > 1 ? picture_size(line.arguments[1]) : std::pair<int, int>(800, 600);
    const auto frames = line.arguments.size() > 2 ? number(line.arguments[2], 2, 2000) : 60L;
    if (!size || !frames || line.arguments.size() > 3) {
      line.fail("'" + line.text +
                "': expected export-animation PATH.webp|PATH.gif [WIDTHxHEIGHT [FRAMES 2-2000]]");
      return true;
    }
    line.done(viewer.export_animation(line.arguments[0], size->first, size->second, int(*frames)));
  } else if (line.command == "save-points") {
    if (line.needs_argument("a .xy path")) line.done(viewer.save_points(line.argument));
  } else if (line.command == "save-result") {
    if (line.needs_argument("a path (.ply .obj .stl .off, or .svg .obj for a curve)"))
      line.done(viewer.save_result(line.argument));
  } else if (line.command == "link") {
    // The link (browser) or command line (desktop) that opens this view, on standard output.
    std::string why_not;
    const std::string link = viewer.link_to_view(why_not);
    if (link.empty()) {
      line.fail("'link': no link to this view: " + why_not);
      return true;
    }
    std::cout << "link: " << link << std::endl;
  } else if (line.command == "stats") {
    // The shown reconstruction's statistics, one JSON line on standard output.
    if (!viewer.has_reconstruction()) {
      line.fail("'stats': no reconstruction on screen");
      return true;
    }
    std::cout << "stats: " << viewer.statistics_line() << std::endl;
  } else {
    return false;
  }
  return true;
}

}  // namespace sculpt::viewer
