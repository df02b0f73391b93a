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

// What a panel's text says of its result, in numbers a test checks on the panel's own input
// (tests/figures_test.cpp): a panel that says "closed as one manifold" or "non-manifold
// edges" must show that, or its text is wrong.
struct Count_range {
  long at_least = 0;
  long at_most = -1;  // -1: no bound
};

struct Claim {
  bool asserted = false;
  bool closed_manifold = false;    // true: no border edge, no non-manifold edge or vertex
  Count_range non_manifold_edges;  // on three triangles or more
  long components = 0;             // exactly this many pieces (0: not said)
  Count_range samples_left_off;    // samples on no triangle
  Count_range border_edges;        // edges on one triangle only
  long border_loops = -1;          // exactly this many loops of border edges (-1: not said)
};

struct Figure_image {
  std::string suffix;   // "a", "b", ... ("" for a single image)
  std::string what;     // what the panel shows, in a few words
  std::string why;      // what changed from the panel before, and why it matters (our words)
  frontend::Shot shot;  // its input: an example, or "cgal:NAME.off" for a CGAL mesh
  Claim claim = {};
};

struct Figure {
  std::string id;           // "fig06"
  std::string caption;      // the paper's caption
  std::string sentence;     // the paper's own description of the figure, quoted from its text
  std::string data;         // what we draw it from
  std::string differences;  // what differs from the paper, and why
  std::vector<Figure_image> images;
  // Where our input makes the paper method contradict the caption: one sentence the tour's
  // caption strip always shows (the differences above are read on demand).
  std::string contradiction = {};
};

const std::vector<Figure>& paper_figures();

// The figure with this id ("fig06"; "6" and "fig6" are accepted too), or nullptr.
const Figure* find_figure(const std::string& id);

// "Fig. 6 (c)": how a panel is named in text.
std::string panel_name(const Figure& figure, std::size_t panel);

}  // namespace sculpt::figures
