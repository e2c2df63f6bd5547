// tinygltf's implementation, compiled into facet::import from Debian's header (libtinygltf-dev)
// rather than linked from Debian's libtinygltf.so: a class the header defines inline (TinyGLTF)
// does not match that library's build, and a program mixing the two frees memory it never
// allocated. Compiled here it also gets the fuzz build's instrumentation. No stb: facet decodes
// images itself (gltf_load.cpp keeps their bytes), and the core already has stb_image inside:
// TINYGLTF_NO_STB_IMAGE and _WRITE are defined for the whole target (cmake/Libraries.cmake),
// since the header's own class reads them.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
