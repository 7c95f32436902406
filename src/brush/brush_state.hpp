// brush/brush_state.hpp — what a BrushCanvas holds (tessera/brush.hpp): its palette (the
// exemplars, each indexed once), the arrangement, and per sample the orientation o(s), the
// scale-free reference offset of the sample in its element (the element graph's original
// displacements p^' of Eq. 4 come from these) and per element its palette entry kappa.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "tessera/brush.hpp"
#include "tessera/grow.hpp"

namespace tessera::brush {

class Surface;  // brush/surface.hpp

// One input sample's neighbourhood (Eq. 1): its neighbours' offsets p^(s'_i, s_i) in the
// exemplar's frame, their weights w_s and output types.
struct InputNeighbourhood {
    int sample = -1;  // index into the exemplar's samples
    int type = -1;    // output type of the sample
    double weight = 0.0;
    std::vector<Vec3> offsets;
    std::vector<double> weights;
    std::vector<int> types;
    // 1 / (weights[k] + weight): Eq. 1's w_scale is (summed output weights) * inverse_summed[k],
    // a product in the pairing's inner loop instead of a division.
    std::vector<double> inverse_summed;
};

struct PaletteEntry {
    std::string name;
    Exemplar exemplar;
    std::vector<int> out_type;  // exemplar type -> output type
    double spacing = 1.0;       // mean nearest-neighbour distance of the element centres
    double radius = 1.0;        // neighbourhood radius of Eq. 1 (BrushOptions::radius spacings)
    std::vector<std::vector<double>> weights;                 // per type, per sample id
    std::vector<std::vector<std::array<int, 2>>> graph;       // per type
    std::vector<InputNeighbourhood> neighbourhoods;           // per input sample (inner ones)
    // The input neighbourhoods of each type and sample id: a sample is matched only with input
    // samples at the same place in their element (a stick's tip with tips).
    std::vector<std::vector<std::vector<int>>> by_type;
    std::shared_ptr<const Grower> grower;                     // indexed once, copied per call
};

// The output types: each is one type of one palette entry.
struct OutType {
    int kappa = 0;
    int type = 0;
};

// A sample's search result (Eq. 2): the input neighbourhood it matched, and for each of its
// output neighbours the input neighbour paired with it (-1: unpaired).
struct Match {
    int neighbourhood = -1;
    double cost = 0.0;
};

}  // namespace tessera::brush

namespace tessera {

struct BrushCanvas::Impl {
    Domain domain;
    BrushOptions options;
    int dimension = 2;
    Progress progress;

    std::vector<brush::PaletteEntry> palette;
    std::vector<std::string> names;
    std::vector<brush::OutType> out_types;

    Arrangement arrangement;
    std::vector<Vec3> direction;  // per sample: o(s), a unit vector (z = 0 in 2D)
    std::vector<Vec3> reference;  // per sample: offset from its element's centre in the element's own frame
    std::vector<Quat> relative;   // per element: its rotation in the frame of its first sample's o(s)
    std::vector<Stroke> strokes;  // direction strokes (paint strokes too)
    std::uint64_t next_id = 0;
    // A surface canvas (the paper's Figure 1b; brush/canvas_surface.hpp): the mesh its elements
    // sit on; null on planes and volumes.
    std::shared_ptr<const brush::Surface> surface;

    int kappa_of_element(int e) const { return out_types[arrangement.elements[e].type].kappa; }
    double weight_of_sample(int s) const;
    // Where elements may be (grown, matched, kept): the canvas, or a surface's band.
    const Domain& space() const;
    // The local frame of sample s (Eq. 1, 4): its o(s) as x; on a surface, z is the normal there.
    Quat frame_of_sample(int s) const;
    // The frame of element e with its centre at c (rigid shapes, element poses).
    Quat frame_of_element(int e, const Vec3& c) const;
    // The palette spacing of a sample's exemplar.
    double spacing_of_sample(int s) const { return palette[kappa_of_element(arrangement.samples[s].element)].spacing; }
};

}  // namespace tessera
