# SPDX-License-Identifier: GPL-3.0-or-later
# Writes OUTPUT, a C++ file that holds each GLSL file of SHADER_DIR as a string constant named
# after it (points.vert -> points_vert), so the programs need no files at run time.
file(GLOB shader_files "${SHADER_DIR}/*.vert" "${SHADER_DIR}/*.frag")
list(SORT shader_files)
set(content "// Generated from shaders/ by cmake/embed_shaders.cmake: do not edit.\n")
string(APPEND content "#include \"render/shader_sources.hpp\"\n\nnamespace sculpt::render::shaders {\n")
foreach(file IN LISTS shader_files)
  get_filename_component(name "${file}" NAME)
  string(REPLACE "." "_" symbol "${name}")
  file(READ "${file}" source)
  string(APPEND content "const char* const ${symbol} = R\"glsl(${source})glsl\";\n")
endforeach()
string(APPEND content "}  // namespace sculpt::render::shaders\n")
file(WRITE "${OUTPUT}.new" "${content}")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
