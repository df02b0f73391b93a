// SPDX-License-Identifier: GPL-3.0-or-later
// The OpenGL functions the renderer calls, declared for the platform: OpenGL 3.3 core on the
// desktop (libOSMesa headless and libOpenGL in a window both export every gl* function, so one
// renderer source serves both; the executable picks the library it links), OpenGL ES 3.0 in the
// browser (WebGL 2, through Emscripten). The renderer uses only what both have.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#endif

namespace sculpt::render {

// The first line every shader starts with (shaders/ hold none): GLSL 3.30 core on the desktop,
// GLSL ES 3.00 in the browser, whose fragment shaders must also choose a float precision.
#ifdef __EMSCRIPTEN__
inline constexpr const char* shader_header = "#version 300 es\nprecision highp float;\n";
#else
inline constexpr const char* shader_header = "#version 330 core\n";
#endif

}  // namespace sculpt::render
