// OpenGL 3.3 core functions, called directly: libOSMesa (headless) and libOpenGL (window) both
// export every gl* function, so one renderer source serves both; the executable picks the
// library it links.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
