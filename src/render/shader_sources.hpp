// SPDX-License-Identifier: GPL-3.0-or-later
// The GLSL programs of shaders/, compiled into the binary (see cmake/embed_shaders.cmake); each
// is compiled after render::shader_header (render/gl.hpp), the platform's #version line.
#pragma once

namespace sculpt::render::shaders {

extern const char* const points_vert;
extern const char* const points_frag;
extern const char* const lines_vert;
extern const char* const flat_frag;
extern const char* const mesh_vert;
extern const char* const mesh_frag;
extern const char* const balls_vert;
extern const char* const balls_frag;
extern const char* const screen_vert;

}  // namespace sculpt::render::shaders
