// Layered exemplars (a wall one brick thick, a sheet of rods on a floor) are thinner than a
// neighbourhood along some axis. The initialization cannot take a cubic window of patch
// size from them: along thin axes its windows span the whole layer, and each output cell's
// window is slid along the (field-turned) thin axis onto the domain, so that a shell under
// a surface receives one layer.
#pragma once

#include "tessera/domain.hpp"

namespace tessera::det {

// Axes along which the exemplar is thinner than one neighbourhood diameter (2 x radius).
struct LayerAxes {
    bool thin[3] = {false, false, false};
    bool any = false;
};

LayerAxes layer_axes(const Box& in_box, int dimension, double radius);

// Slides a cell's window centre along each thin axis (turned by `rotation`) to the middle
// of the nearest run of domain inside that line, within +-patch.
Vec3 onto_layer(const Vec3& center, const Quat& rotation, const LayerAxes& layer, const Box& in_box,
                const Domain& domain, double patch, int dimension);

}  // namespace tessera::det
