// stb_image and stb_image_write (Debian's libstb 2022-09-08), compiled with the fuzz build's
// sanitizers and coverage; they take the place of libstb's copies in the fuzz executables only.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
