// SPDX-License-Identifier: GPL-3.0-or-later
#include "viewer/lessons.hpp"

#include <sstream>

namespace sculpt::viewer {

std::string lesson_title(const Lesson& lesson) {
  std::istringstream lines(lesson.script);
  std::string line;
  while (std::getline(lines, line)) {
    const auto start = line.find_first_not_of("# \t");
    if (line.rfind('#', 0) == 0 && start != std::string::npos &&
        line.find("SPDX-License-Identifier") == std::string::npos)
      return line.substr(start);
  }
  return lesson.name;
}

}  // namespace sculpt::viewer
