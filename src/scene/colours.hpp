// SPDX-License-Identifier: GPL-3.0-or-later
// The colour schemes a picture can be drawn in: the paper's (palette.hpp) and one for readers
// with a red-green colour vision deficiency, in which every pair of layers that one picture
// shows stays apart as people with deuteranopia and protanopia see them
// (tests/palette_test.cpp simulates both).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sculpt::scene {

enum class Colours { paper, colour_blind };

const char* colours_name(Colours colours);  // "paper", "colour-blind"
bool parse_colours(const std::string& name, Colours& colours);
const std::vector<std::string>& colours_names();

// Redraws the scene's layers in the scheme (the paper's: unchanged). Opacity stays.
void recolour(Scene& scene, Colours colours);

}  // namespace sculpt::scene
