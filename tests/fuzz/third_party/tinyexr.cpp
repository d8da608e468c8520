// tinyexr's implementation, compiled with the fuzz build's sanitizers and coverage so that the
// fuzzer sees inside it. These definitions take the place of Debian's libtinyexr (same
// version, 1.0.1, same options: zlib, no threads, no OpenMP) in the fuzz executables only.
#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>
