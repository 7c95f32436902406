// The demo's run past the round obstacle (scripts/demo, `obstacle`): the swirl particles of
// examples/dynamic/swirl_particles_2d.json carried by a flow of (1.5, 0) through the channel
// of examples/dynamic/obstacle_channel.json, wrapped, on two threads.
#pragma once

#include <string>

#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/io.hpp"

namespace dynamic_test {

constexpr double hole_x = 10.0, hole_y = 7.3, hole_r = 2.5;  // the channel's round obstacle

struct ObstacleDemo {
    tessera::Animation exemplar;
    tessera::Domain domain;
    tessera::DynamicOptions options;
};

inline ObstacleDemo obstacle_demo(int frames) {
    const std::string root = std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/";
    ObstacleDemo demo{tessera::load_animation(root + "swirl_particles_2d.json"),
                      tessera::load_domain_json(root + "obstacle_channel.json", 2), {}};
    demo.options.frames = frames;
    demo.options.flow = {1.5, 0, 0};
    demo.options.wrap = true;
    demo.options.threads = 2;
    return demo;
}

}  // namespace dynamic_test
