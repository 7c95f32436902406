// Helpers of the glTF tests: the JSON document and the binary buffer of a written .gltf
// (buffer embedded as a base64 data URI) or .glb (JSON chunk + BIN chunk).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gltf_test {

using Json = nlohmann::json;

inline std::vector<unsigned char> base64_decode(const std::string& text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> out;
    unsigned value = 0;
    int bits = 0;
    for (char c : text) {
        if (c == '=') break;
        const size_t d = alphabet.find(c);
        if (d == std::string::npos) continue;
        value = (value << 6) | static_cast<unsigned>(d);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>((value >> bits) & 0xff));
        }
    }
    return out;
}

inline std::uint32_t u32(const std::string& bytes, size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

struct GltfFile {
    Json doc;
    std::vector<unsigned char> buffer;
};

// Parses the bytes of a .glb (when they start with "glTF") or of a .gltf with its buffer
// embedded. Failures are gtest assertions; the result is then empty.
inline GltfFile parse_gltf(const std::string& bytes) {
    GltfFile file;
    if (bytes.compare(0, 4, "glTF") == 0) {
        EXPECT_GE(bytes.size(), 28u);
        if (bytes.size() < 28) return file;
        const std::uint32_t json_length = u32(bytes, 12);
        EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au);  // "JSON"
        file.doc = Json::parse(bytes.substr(20, json_length));
        const size_t bin = 20 + json_length;
        EXPECT_EQ(u32(bytes, bin + 4), 0x004E4942u);  // "BIN"
        file.buffer.assign(bytes.begin() + static_cast<long>(bin + 8), bytes.end());
        return file;
    }
    file.doc = Json::parse(bytes);
    const std::string uri = file.doc["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    EXPECT_EQ(uri.rfind(prefix, 0), 0u);
    file.buffer = base64_decode(uri.substr(prefix.size()));
    return file;
}

// tessera's glTF files hang every node under one root node, the last of "nodes" and the
// scene's only root, which turns tessera's z-up to glTF's +y up (-90 degrees about x).
// Checks that root and returns the nodes below it (the data's, in their order).
inline Json content_nodes(const Json& doc) {
    const Json& nodes = doc["nodes"];
    EXPECT_EQ(doc["scenes"][0]["nodes"].size(), 1u);
    if (nodes.empty()) return Json::array();
    const size_t root_index = nodes.size() - 1;
    EXPECT_EQ(doc["scenes"][0]["nodes"][0].get<size_t>(), root_index);
    const Json& root = nodes[root_index];
    EXPECT_FALSE(root.contains("mesh"));
    const Json& r = root["rotation"];  // x, y, z, w
    EXPECT_NEAR(r[0].get<double>(), -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(r[1].get<double>(), 0.0, 1e-12);
    EXPECT_NEAR(r[2].get<double>(), 0.0, 1e-12);
    EXPECT_NEAR(r[3].get<double>(), std::sqrt(0.5), 1e-12);
    EXPECT_EQ(root["children"].size(), root_index);
    Json content = Json::array();
    for (size_t i = 0; i < root_index; ++i) content.push_back(nodes[i]);
    return content;
}

// The float components of accessor `index` (tightly packed float data).
inline std::vector<float> floats(const GltfFile& file, size_t index) {
    const Json& a = file.doc["accessors"][index];
    const Json& view = file.doc["bufferViews"][a["bufferView"].get<size_t>()];
    const size_t start = view.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    const size_t n = view["byteLength"].get<size_t>() / 4;
    std::vector<float> out(n);
    std::memcpy(out.data(), file.buffer.data() + start, n * 4);
    return out;
}

}  // namespace gltf_test
