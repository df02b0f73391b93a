// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's figures as data: for each figure its caption, the sentence of the paper that
// describes it, and its panels, each a shot of one of our reconstructions with a sentence on
// what it shows and what changed from the panel before. One list drives both the headless
// gallery (`sculpt figures`) and the viewer's tour (Paper menu, `sculpt-view --figure`).
#pragma once

#include <string>
#include <vector>

#include "frontend/shot.hpp"

namespace sculpt::figures {

struct Figure_image {
  std::string suffix;   // "a", "b", ... ("" for a single image)
  std::string what;     // what the panel shows, in a few words
  std::string why;      // what changed from the panel before, and why it matters (our words)
  frontend::Shot shot;  // its input: an example, or "cgal:NAME.off" for a CGAL mesh
};

struct Figure {
  std::string id;           // "fig06"
  std::string caption;      // the paper's caption
  std::string sentence;     // the paper's own description of the figure, quoted from its text
  std::string data;         // what we draw it from
  std::string differences;  // what differs from the paper, and why
  std::vector<Figure_image> images;
};

const std::vector<Figure>& paper_figures();

// The figure with this id ("fig06"; "6" and "fig6" are accepted too), or nullptr.
const Figure* find_figure(const std::string& id);

// "Fig. 6 (c)": how a panel is named in text.
std::string panel_name(const Figure& figure, std::size_t panel);

}  // namespace sculpt::figures
