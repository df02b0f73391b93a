# SPDX-License-Identifier: GPL-3.0-or-later
# Fails, naming them, when a source file of the project lacks its licence line
# (SPDX-License-Identifier: GPL-3.0-or-later) among its first three lines: C++, C, GLSL,
# JavaScript, TypeScript, Python, CMake, the lessons and the shell scripts.
# cmake -DSOURCE_DIR=... -P source_licence_check.cmake
set(patterns *.cpp *.hpp *.c *.h *.vert *.frag *.mjs *.js *.ts *.py *.cmake *.script
             CMakeLists.txt)
set(folders src include tests fuzz examples python scripts web shaders cmake .ci docs)
set(sources ${SOURCE_DIR}/CMakeLists.txt)
foreach(folder ${folders})
  foreach(pattern ${patterns})
    file(GLOB_RECURSE found ${SOURCE_DIR}/${folder}/${pattern})
    list(APPEND sources ${found})
  endforeach()
endforeach()
# Shell scripts: the files of scripts/ and .ci/ that start with #!.
foreach(folder scripts .ci tests/install docs/tools)
  file(GLOB found ${SOURCE_DIR}/${folder}/*)
  foreach(file ${found})
    file(READ ${file} start LIMIT 2)
    if(start STREQUAL "#!")
      list(APPEND sources ${file})
    endif()
  endforeach()
endforeach()
list(FILTER sources EXCLUDE REGEX "/node_modules/|/fuzz/corpus/|/fuzz/regressions/")
list(REMOVE_DUPLICATES sources)
set(missing "")
foreach(file ${sources})
  file(STRINGS ${file} head LIMIT_COUNT 3)
  if(NOT head MATCHES "SPDX-License-Identifier: GPL-3.0-or-later")
    string(APPEND missing "\n  ${file}")
  endif()
endforeach()
list(LENGTH sources count)
if(missing)
  message(FATAL_ERROR "source files without their licence line (SPDX-License-Identifier: "
                      "GPL-3.0-or-later):${missing}")
endif()
message(STATUS "${count} source files, each with its licence line")
