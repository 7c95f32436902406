// apps/tessera/synth_dynamic.hpp — `tessera synth --method dynamic` (or an INPUT with
// frames): reads the animated exemplar, synthesizes frame by frame, writes the animation
// (.json / .csv with frames, or an animated .png) and an optional animated --preview.
#pragma once

#include <functional>
#include <string>

#include "tessera/domain.hpp"
#include "tessera/dynamic.hpp"

namespace tessera_cli {

class StatusPrinter;

struct DynamicRun {
    std::string input, input_domain, output, preview;
    std::string coarse;  // --coarse: all-frame synthesis on this coarse motion (else frame by frame)
    tessera::DynamicOptions options;
    bool quiet = false;
};

// Checks the output paths before anything runs (Error(option) naming -o or --preview).
void check_dynamic_outputs(const DynamicRun& run);

// Runs the synthesis into domain_of(the exemplar's frame 0) and writes the files.
void run_dynamic(const DynamicRun& run, StatusPrinter& status,
                 const std::function<tessera::Domain(const tessera::Exemplar&)>& domain_of);

}  // namespace tessera_cli
