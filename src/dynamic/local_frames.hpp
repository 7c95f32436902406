// Local frames of a coarse motion: the orientation field that guides the detail of threads
// and sheets (Dynamic Element Textures, section 3.2: "the directions ... are determined by
// orientation fields"). Details are stored in the frame of the coarse geometry at their
// sample (x along the thread or the sheet's columns, y across, z the sheet's normal in 3D), so
// that the wiggle of a hanging noodle carries over to a noodle lying sideways, and a sheet's
// flutter stays along its normal however the sheet tumbles.
#pragma once

#include <vector>

#include "dynamic/topology_grid.hpp"
#include "tessera/animation.hpp"

namespace tessera::dynamic {

struct LocalFrame {
    Vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // orthonormal
    Vec3 to_local(const Vec3& v) const { return {dot(v, axis[0]), dot(v, axis[1]), dot(v, axis[2])}; }
    Vec3 to_world(const Vec3& v) const { return axis[0] * v.x + axis[1] * v.y + axis[2] * v.z; }
};

// The frame of every sample at every frame (frame-major, like Animation::positions): along
// the thread (central differences, one-sided at the ends) with the normal carried along the
// thread from its first sample (parallel transport, so the frame does not twist where the
// tangent passes an axis); on a sheet the column direction and the normal of the surface;
// the identity for particles.
std::vector<LocalFrame> local_frames(const Animation& coarse, const TopologyGrid& grid);

}  // namespace tessera::dynamic
