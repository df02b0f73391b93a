// SPDX-License-Identifier: GPL-3.0-or-later
// The tour of the paper's figures: which figure and panel the viewer shows, in the order of
// paper_figures(), and whether the student has left the panel to explore. Navigation only;
// the viewer turns a panel into a reconstruction, a stage and a camera.
#pragma once

#include <cstddef>
#include <string>

#include "figures/paper_figures.hpp"

namespace sculpt::viewer {

class Tour {
 public:
  bool active() const { return figure_ != nullptr; }
  bool exploring() const { return active() && exploring_; }
  const figures::Figure& figure() const { return *figure_; }
  std::size_t panel() const { return panel_; }
  const figures::Figure_image& image() const { return figure_->images[panel_]; }
  // "fig06c" (or "fig03" for a figure of one panel), "" when no tour runs.
  std::string panel_id() const;
  std::string panel_name() const { return figures::panel_name(*figure_, panel_); }

  // Each returns false, and changes nothing, when there is no such panel.
  bool open(const figures::Figure& figure, std::size_t panel = 0);
  bool next();      // the next panel, or the first of the next figure
  bool previous();  // the previous panel, or the last of the previous figure
  bool next_figure();
  bool previous_figure();
  // Parses "next", "previous", "3" (1-based) or "c" and goes there.
  bool go_to(const std::string& panel);

  void explore() { exploring_ = true; }
  void return_to_panel() { exploring_ = false; }
  void close() { figure_ = nullptr, exploring_ = false; }

 private:
  std::size_t figure_index() const;

  const figures::Figure* figure_ = nullptr;
  std::size_t panel_ = 0;
  bool exploring_ = false;
};

}  // namespace sculpt::viewer
