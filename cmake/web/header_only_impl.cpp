// The implementations of the header-only libraries the web build uses (tinygltf, stb_image, stb_image_write), in
// one translation unit of their own. The native build links Debian's compiled libtinygltf and libstb instead, so
// this file is only in the web build (cmake/web.cmake). Nothing else may define these *_IMPLEMENTATION macros.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
// tiny_gltf.h includes stb_image.h and stb_image_write.h itself.
#include <tiny_gltf.h>
