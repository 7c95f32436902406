// Geometry of a PCF model picture (tessera/pcf_plot.hpp), computed once and drawn by
// both writers (plot_svg.cpp, plot_png.cpp) so that the SVG and the PNG show the same
// thing: panel frames, value ranges, ticks, titles and curves in pixel coordinates.
#pragma once

#include <string>
#include <vector>

#include "render/palette.hpp"
#include "tessera/pcf_plot.hpp"

namespace tessera::pcf {

struct PlotPoint {
    double x = 0, y = 0;
};

struct PlotTick {
    double at = 0;       // pixel coordinate along the axis
    std::string label;
};

struct PlotPanel {
    double left = 0, top = 0, right = 0, bottom = 0;   // the plotting area, pixels
    std::string title;
    render::Rgb color;                                 // the child class's colour
    std::vector<PlotPoint> mean, lower, upper;         // clipped to the plotting area
    std::vector<PlotPoint> measured;                   // empty when not drawn
    std::vector<PlotTick> x_ticks, y_ticks;
    double one_y = -1;                                 // pixel y of PCF = 1 (-1: out of range)
    std::vector<double> salient_x;                     // pixel x of x = 1, 2, 3 (disk models)
};

struct PlotLayout {
    int width = 0, height = 0;
    std::vector<PlotPanel> panels;
    std::vector<std::string> footer;                   // lines of notes under the panels
    double footer_y = 0;                               // top of the notes
    double footer_line = 14;                           // their line spacing, pixels
};

// Checks the options (Error(option)) and lays the model's PCFs out.
PlotLayout plot_layout(const PcfModel& model, const PcfPlotOptions& options);

}  // namespace tessera::pcf
