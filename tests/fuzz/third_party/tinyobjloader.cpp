// tinyobjloader's implementation (Debian's 2.0.0rc10, float), compiled with the fuzz build's
// sanitizers and coverage; it takes the place of libtinyobjloader in the fuzz executables only.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
