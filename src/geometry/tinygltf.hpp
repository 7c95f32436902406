// geometry/tinygltf.hpp — tinygltf (libtinygltf-dev) as the library uses it: the glTF
// data model and writer only. It reads and writes JSON with the system nlohmann json
// the library already links, and leaves out image decoding and encoding (no textures
// are written) and loading external images. Every file that includes tiny_gltf.h goes
// through here so that all of them see the same configuration.
#pragma once

#include <nlohmann/json.hpp>

#define TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
