# SPDX-License-Identifier: GPL-3.0-or-later
# Writes OUTPUT, a C++ file that holds each lesson of LESSON_DIR (NAME.script) as text, so that
# `sculpt-view --lesson NAME` and the browser's ?lesson=NAME need no files at run time.
file(GLOB lesson_files "${LESSON_DIR}/*.script")
list(SORT lesson_files)
set(content "// Generated from examples/lessons/ by cmake/embed_lessons.cmake: do not edit.\n")
string(APPEND content "#include \"viewer/lessons.hpp\"\n\nnamespace sculpt::viewer {\n\n")
string(APPEND content "const std::vector<Lesson>& lessons() {\n  static const std::vector<Lesson> all = {\n")
foreach(file IN LISTS lesson_files)
  get_filename_component(name "${file}" NAME_WE)
  file(READ "${file}" text)
  string(APPEND content "      {\"${name}\", R\"lesson(${text})lesson\"},\n")
endforeach()
string(APPEND content "  };\n  return all;\n}\n\n}  // namespace sculpt::viewer\n")
file(WRITE "${OUTPUT}.new" "${content}")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
