// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's figures and tables, regenerated headless: `generate` renders the shots of every
// figure of paper_figures.hpp (built-in shapes or CGAL's meshes from Debian's libcgal-demo),
// writes Tables 1 and 2 as Markdown, a manifest, and the gallery page figures/README.md.
#pragma once

#include <string>
#include <vector>

#include "paper_figures.hpp"

namespace sculpt::figures {

struct Options {
  std::string out = "figures";
  std::string only;  // a figure id, or "" for all
  std::string cgal_archive = "/usr/share/doc/libcgal-demo/data.tar.gz";
  std::string size = "700x700";
};

// Throws io::Error with a one-line message. Returns the number of images written.
int generate(const Options& options);

}  // namespace sculpt::figures
