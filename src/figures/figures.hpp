// The paper's figures and tables, regenerated headless: each figure is a list of shots of our
// own reconstructions (built-in shapes or CGAL's meshes from Debian's libcgal-demo), and
// `generate` renders them, writes Tables 1 and 2 as Markdown, a manifest, and the gallery page
// figures/README.md.
#pragma once

#include <string>
#include <vector>

#include "frontend/shots.hpp"

namespace sculpt::figures {

struct Figure_image {
  std::string suffix;   // "a", "b", ... ("" for a single image)
  std::string what;     // what the panel shows
  frontend::Shot shot;  // its input: an example, or "cgal:NAME.off" for a CGAL mesh
};

struct Figure {
  std::string id;           // "fig06"
  std::string caption;      // the paper's caption
  std::string data;         // what we draw it from
  std::string differences;  // what differs from the paper, and why
  std::vector<Figure_image> images;
};

const std::vector<Figure>& paper_figures();

struct Options {
  std::string out = "figures";
  std::string only;  // a figure id, or "" for all
  std::string cgal_archive = "/usr/share/doc/libcgal-demo/data.tar.gz";
  std::string size = "700x700";
};

// Throws io::Error with a one-line message. Returns the number of images written.
int generate(const Options& options);

}  // namespace sculpt::figures
