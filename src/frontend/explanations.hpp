// SPDX-License-Identifier: GPL-3.0-or-later
// What each stage of each method shows, for a class: a short paragraph (what is drawn, why it
// matters, what to look for) that the viewer's Explanation panel and its `explain` script
// command give for the stage on screen.
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>

#include "scene/scene.hpp"

namespace sculpt::frontend {

// The paragraph for this stage as the method runs it (kind and dimension change some of them).
std::string explanation(Method method, Surface_kind kind, int dimension, scene::Stage stage);

}  // namespace sculpt::frontend
