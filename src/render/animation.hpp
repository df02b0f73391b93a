// SPDX-License-Identifier: GPL-3.0-or-later
// An animation of pictures (the replay of the labelling, a sweep through the stages) as an
// animated WebP (libwebpmux), which browsers, slide software and image viewers play.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"

namespace sculpt::render {

// Writes the frames, all of one size, each shown `milliseconds` (the last one held three times
// as long, so a loop pauses on the result), losslessly: thin lines stay sharp. All or nothing;
// throws std::runtime_error with a one-line message.
void write_animation(const std::string& path, const std::vector<Image>& frames, int milliseconds);

}  // namespace sculpt::render
