// Animations with every kind of element the animated scene writers draw, built in code so
// that the tests know each sample's position at each frame: particles circling, threads
// swaying, a sheet waving and (optionally) a rigid mesh element turning about z.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "tessera/animation.hpp"

namespace animated_test {

using tessera::Animation;
using tessera::ElementTopology;
using tessera::Exemplar;
using tessera::Vec3;

constexpr int sheet_rows = 4, sheet_columns = 5, thread_samples = 10;
constexpr double frame_step = 0.125;  // seconds between frames
constexpr double shard_turn = 0.3;    // radians about z per frame

// The shard's samples around its centroid: an asymmetric tetrahedron.
inline std::vector<Vec3> shard_layout() {
    return {{-0.5, -0.2, -0.1}, {0.9, -0.1, 0.0}, {0.0, 0.6, 0.05}, {0.1, 0.1, 0.7}};
}

// Element e's samples at frame f. Elements, in order (ids 10, 11, ...): dot 0, noodle 0,
// cloth, dot 1, noodle 1, shard (when there is one), dot 2, noodle 2 (no radius).
inline std::vector<Vec3> samples_at(const std::string& type, int index, int f) {
    std::vector<Vec3> p;
    if (type == "dot") {
        const double w = 0.7 * f + index;
        p.push_back({2.0 * index + 0.3 * std::cos(w), 0.3 * std::sin(w), 0.1 * index});
    } else if (type == "noodle") {
        for (int k = 0; k < thread_samples; ++k)
            p.push_back({0.3 * k + 0.05 * k * std::sin(0.6 * f + index), 3.0 + index,
                         0.2 * std::sin(0.5 * f + 0.4 * k + index)});
    } else if (type == "cloth") {
        for (int r = 0; r < sheet_rows; ++r)
            for (int c = 0; c < sheet_columns; ++c)
                p.push_back({6.0 + 0.5 * c, 0.5 * r, 0.3 * std::sin(0.8 * f + 0.9 * c + 0.3 * r)});
    } else {  // shard
        const double a = shard_turn * f, c = std::cos(a), s = std::sin(a);
        for (const Vec3& v : shard_layout())
            p.push_back(Vec3{c * v.x - s * v.y + 0.1 * f, s * v.x + c * v.y - 3.0, v.z + 0.5});
    }
    return p;
}

// `frames` frames at times t0 + frame_step x f. With `shard_mesh` (an OBJ file) a rigid
// type "shard" with that mesh and one element is added.
inline Animation mixed_animation(int frames, const std::string& shard_mesh = "", double t0 = 0.0) {
    Exemplar ex;
    ex.dimension = 3;
    for (const char* name : {"dot", "noodle", "cloth"}) ex.type_index(name);
    ex.types[0].topology = ElementTopology::none;
    ex.types[1].topology = ElementTopology::thread;
    ex.types[2].topology = ElementTopology::sheet;
    ex.types[2].sheet_columns = sheet_columns;
    std::vector<std::pair<std::string, int>> order = {{"dot", 0}, {"noodle", 0}, {"cloth", 0}, {"dot", 1}, {"noodle", 1}};
    if (!shard_mesh.empty()) {
        ex.types[static_cast<size_t>(ex.type_index("shard"))].mesh = shard_mesh;
        order.push_back({"shard", 0});
    }
    order.insert(order.end(), {{"dot", 2}, {"noodle", 2}});
    for (const auto& [type, index] : order) {
        const double radius = type == "dot" ? 0.2 : (type == "noodle" && index < 2 ? 0.05 : 0.0);
        const int e = ex.add_element(ex.find_type(type), samples_at(type, index, 0), radius);
        ex.elements[e].id = 10 + static_cast<std::uint64_t>(e);
    }
    ex.domain = tessera::Domain::box({-1, -4, -1}, {9, 6, 2}, 3);
    Animation a;
    a.structure = ex;
    for (int f = 0; f < frames; ++f) {
        std::vector<Vec3> positions;
        for (const auto& [type, index] : order)
            for (const Vec3& p : samples_at(type, index, f)) positions.push_back(p);
        a.add_frame(t0 + frame_step * f, positions);
    }
    a.validate("mixed_animation");
    return a;
}

}  // namespace animated_test
