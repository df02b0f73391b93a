// SPDX-License-Identifier: GPL-3.0-or-later
// The lessons shipped with the viewer (examples/lessons/NAME.script, compiled in): scripts a
// class watches step by step (Script::Mode::lesson), opened by --lesson NAME, ?lesson=NAME in
// the browser, or the Lessons menu.
#pragma once

#include <string>
#include <vector>

namespace sculpt::viewer {

struct Lesson {
  const char* name;
  const char* script;
};

const std::vector<Lesson>& lessons();

inline const Lesson* find_lesson(const std::string& name) {
  for (const Lesson& lesson : lessons())
    if (name == lesson.name) return &lesson;
  return nullptr;
}

// The lesson's title: the first line of its leading comment block (after its licence line).
std::string lesson_title(const Lesson& lesson);

}  // namespace sculpt::viewer
