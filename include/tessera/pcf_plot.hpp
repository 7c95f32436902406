// tessera/pcf_plot.hpp — pictures of a PCF model (`tessera analyze --plot`), like
// Figures 1, 2 and 10 of Ecormier-Nocca et al. 2019: one small panel per PCF of the
// model, titled "child | parent" (or the class name for a class's own PCF), with the
// mean PCF as a line over the shaded envelope of the individual PCFs, on the normalised
// axis x (pcf_synthesis.hpp). Optionally an arrangement's measured mean PCFs
// (measure_distribution) are drawn over the model's, to compare an output with its input.
#pragma once

#include <string>
#include <vector>

#include "tessera/pcf_synthesis.hpp"

namespace tessera {

struct PcfPlotOptions {
    int panel_width = 300;               // pixels per panel, 120 .. 2000
    int panel_height = 200;              // 90 .. 2000
    int columns = 0;                     // panels per row; 0 = automatic (about square, at most 8)
    std::vector<PcfEnvelope> measured;   // empty, or one per model PCF (same order): drawn as dark lines
};

// The picture as SVG text, or as PNG bytes. Throws Error(option) for bad options (sizes,
// a `measured` list that does not match the model's PCFs).
std::string pcf_plot_svg(const PcfModel& model, const PcfPlotOptions& options = {});
std::string pcf_plot_png(const PcfModel& model, const PcfPlotOptions& options = {});

// Writes the picture by the extension of `path` (.svg or .png, case-insensitive),
// atomically. Throws Error(option) naming the path for another extension, Error(io).
void write_pcf_plot(const PcfModel& model, const std::string& path, const PcfPlotOptions& options = {});

}  // namespace tessera
