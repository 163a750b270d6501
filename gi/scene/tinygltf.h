#pragma once
// The one way Lumina includes tinygltf, so every translation unit sees the same
// configuration (TinyGLTF's class layout depends on these macros). Images are not decoded
// by tinygltf: gltf_textures.cpp decodes the ones materials use, with its own limits, and
// nothing is ever written through tinygltf.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
