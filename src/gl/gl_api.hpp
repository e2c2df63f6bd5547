// The OpenGL 3.3 core declarations the GL twin uses. With glvnd, libOpenGL exports every core
// function, so they are called directly (GL_GLEXT_PROTOTYPES) with no loader library.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
