// SPDX-License-Identifier: GPL-3.0-or-later
// Where a run may write, decided before any work: an output goes into a folder that exists, is
// not itself a folder, a pipe or a device, and is never one of the run's inputs, whatever name
// reaches it (a link, `..`, another spelling): renaming a result over an input would destroy the
// only copy of the user's data (a PLY's colours, an OBJ's normals, the repeated points that
// --merge-duplicates drops).
#pragma once

#include <string>
#include <vector>

namespace sculpt::io {

// Throws io::Error, one line naming the user's path, if `path` cannot be an output of a run
// that reads `inputs` (or a file given to remember_input). An empty path is no output.
void check_destination(const std::string& path, const std::vector<std::string>& inputs = {});

// Every output of one run, checked as above, and no two of them the same file.
void check_destinations(const std::vector<std::string>& paths,
                        const std::vector<std::string>& inputs = {});

// A file this process read for the user, outside any one command: what Python's read_points or
// the viewer opened. No later output may replace it (by device and inode, as it was read).
void remember_input(const std::string& path);

}  // namespace sculpt::io
