// tinygltf's implementation, compiled once for lumina_scene.
#define TINYGLTF_IMPLEMENTATION
#include "gi/scene/tinygltf.h"
