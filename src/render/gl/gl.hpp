#pragma once
// Private: the one place render/ includes OpenGL. libOSMesa exports every gl* entry point, so the
// prototypes are used directly (no loader). Never include this from a public header.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
