// SPDX-License-Identifier: MIT
// The OpenGL API as the renderer uses it: plain prototypes (GL_GLEXT_PROTOTYPES), no loader. The
// executable's link line decides where the gl* symbols come from — libOSMesa in lamina-headless
// and the golden tests, libOpenGL in the editor (never both in one program).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
