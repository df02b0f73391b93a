// SPDX-License-Identifier: GPL-3.0-or-later
// Options that would do nothing where they are given. A user who sets --alpha on the robust
// method, --step at the poles or --wireframe on a curve believes the result changed; it did
// not. So a value other than the default, for an option that the chosen method, kind, stage or
// dimension never reads, is refused in one line that says where it does apply, in the words of
// the caller (a flag on the command line, a keyword in Python, a key in a shots file).
#pragma once

#include <sculpt/sculpt.hpp>
#include <string>

#include "frontend/shot.hpp"
#include "scene/scene.hpp"

namespace sculpt::frontend {

enum class Spelling { command_line, python, shots_file };

// Why one of the reconstruction options does not apply to its method and kind (Options'
// defaults stand for "not given"); empty when all of them do.
std::string unused_reconstruction_option(const Options& options, Spelling spelling);

// --dim or --merge-duplicates given with a built-in example: they apply to a point file.
std::string unused_input_option(const std::string& example, int dimension, bool merge_duplicates,
                                Spelling spelling);

// --automatic (Python's kind='automatic') given for a method that does not choose the kind.
std::string unused_automatic_kind(Method method, Spelling spelling);

// --ascii for an output format that has no binary form (OBJ, OFF, SVG, ...); empty for .stl
// and .ply.
std::string unused_ascii(const std::string& output, Spelling spelling);

// Why one of a picture's drawing options does nothing in the scene it drew (Shot's defaults
// stand for "not given"); empty when all of them do. The scene says what is drawn: a shaded
// surface, polar balls, the dimension.
std::string unused_drawing_option(const Shot& shot, const scene::Scene& scene, Spelling spelling);

// Why an animation option does not apply to the shot (its stage, --frames without --animate,
// ...); empty when all do.
std::string unused_animation_option(const Shot& shot, Spelling spelling);

}  // namespace sculpt::frontend
