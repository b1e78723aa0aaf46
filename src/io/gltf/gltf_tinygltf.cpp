// The one translation unit that compiles tinygltf's implementation (see gltf_model.h).
#define TINYGLTF_IMPLEMENTATION
#include "gltf_model.h"
