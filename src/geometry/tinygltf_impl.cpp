// geometry/tinygltf_impl.cpp — the one translation unit compiling tinygltf's
// implementation (it is a header library: exactly one file defines
// TINYGLTF_IMPLEMENTATION), with the configuration of geometry/tinygltf.hpp.
#define TINYGLTF_IMPLEMENTATION
#include "geometry/tinygltf.hpp"
