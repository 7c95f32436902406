// apps/tessera/analyze_decompose.hpp — `tessera analyze ANIM --decompose -o COARSE --detail
// DETAIL`: the analysis of Dynamic Element Textures, section 5 (tessera::decompose_motion):
// an animation's coarse motion and its details (offsets), written as two animations.
#pragma once

#include <string>

#include "tessera/motion_analysis.hpp"

namespace tessera_cli {

struct DecomposeRun {
    std::string input, input_domain, coarse, detail;
    tessera::LowPassOptions options;
    bool quiet = false;
};

// Checks both output paths (Error(option) naming -o or --detail; .json, .csv or .usda, what
// save_animation writes), reads the animation,
// splits it and writes both files, or neither.
void run_decompose(const DecomposeRun& run);

}  // namespace tessera_cli
