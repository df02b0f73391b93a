// SPDX-License-Identifier: GPL-3.0-or-later
// The script's commands that edit a 2D input's samples by hand, as the mouse does.
#include <limits>
#include <vector>

#include "script_line.hpp"

namespace sculpt::viewer {

bool run_edit_command(Script_line& line) {
  Viewer& viewer = line.viewer;
  if (line.command == "edit") {
    line.on_off([&](bool on) {
      if (on && viewer.shown_dimension() == 3) {
        line.fail("'" + line.text + "': samples are edited in 2D; this is a surface");
        return;
      }
      viewer.set_editing(on);
    });
  } else if (line.command == "add-point") {
    const auto xy = line.reals(0);
    if (!xy || xy->size() != 2) {
      line.fail("'" + line.text + "': expected add-point X Y");
      return true;
    }
    line.done(viewer.add_point({(*xy)[0], (*xy)[1]}));
  } else if (line.command == "move-point") {
    const auto sample = line.arguments.empty()
                            ? std::nullopt
                            : number(line.arguments[0], 0, long(std::numeric_limits<int>::max()));
    const auto xy = line.reals(1);
    if (!sample || !xy || xy->size() != 2) {
      line.fail("'" + line.text + "': expected move-point SAMPLE X Y");
      return true;
    }
    line.done(viewer.move_point(int(*sample), {(*xy)[0], (*xy)[1]}));
  } else if (line.command == "delete-point") {
    if (const auto sample =
            line.count("a sample index", 0, long(std::numeric_limits<int>::max()))) {
      line.done(viewer.delete_point(int(*sample)));
    }
  } else if (line.command == "stroke") {
    // stroke SPACING X1 Y1 X2 Y2 ...: a drawn polyline resampled SPACING apart (a share of
    // the samples' box diagonal).
    const auto values = line.reals(0);
    if (!values || values->size() < 5 || values->size() % 2 != 1 || (*values)[0] < 0.001 ||
        (*values)[0] > 1) {
      line.fail("'" + line.text +
                "': expected stroke SPACING X1 Y1 X2 Y2 ... (spacing 0.001 to 1, a share of "
                "the samples' box diagonal)");
      return true;
    }
    std::vector<Point<2>> stroke;
    for (std::size_t i = 1; i + 1 < values->size(); i += 2)
      stroke.push_back({(*values)[i], (*values)[i + 1]});
    line.done(viewer.add_stroke(stroke, (*values)[0]));
  } else if (line.command == "undo") {
    line.done(viewer.undo_edit());
  } else {
    return false;
  }
  return true;
}

}  // namespace sculpt::viewer
