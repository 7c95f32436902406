// Spatio-temporal neighbourhoods (Dynamic Element Textures, Eq. 2-3 and Figure 3): the
// differences u(s') - u(s) of the samples around a centre sample, grouped by time offset
// k = 0, 1, ..., T - 1 (frames back from the centre's: temporal-causal, so that frame-by-
// frame synthesis never reads a frame it has not made; or, for all-frame synthesis, frames
// on both sides: temporal-non-causal, StParams::ahead). Eq. 4 pairs only entries of equal
// time offset, so a group is the unit of the Hungarian pairing.
//   compact shape: group 0 = the spatial neighbours at the centre's frame, group k >= 1 =
//                  the centre's own sample k frames back (its 1D temporal trail);
//   full shape:    group k = every sample within the radius at frame t - k.
#pragma once

#include <array>
#include <vector>

#include "tessera/dynamic.hpp"
#include "tessera/vec.hpp"

namespace tessera::dynamic {

constexpr int max_temporal = 16;  // bound on DynamicOptions::temporal_size (the option table's)
constexpr int max_group = 48;     // entries kept per group: the nearest ones

// Everything the metric and the gathering need, resolved once per run.
struct StParams {
    int dimension = 2;
    NeighbourhoodShape shape = NeighbourhoodShape::compact;
    int temporal = 3;             // T: frames per neighbourhood
    double radius = 1.0;          // r: output neighbourhoods gather within r
    double input_radius = 1.5;    // input neighbourhoods gather further (r + one spacing), so an
                                  // output neighbour near r still finds its partner
    double cap2 = 1.0;            // a pair costs at most this (an unpaired entry costs it)
    double alpha = 1.0;           // type mismatch cost (squared length)
    double inv_sigma_p2 = 0.0;    // Eq. 10: 1 / sigma_p^2 (absolute units), 0 = no falloff
    double inv_sigma_t2 = 0.0;    // 1 / sigma_t^2 (frames), 0 = no falloff
    double spacing = 1.0;         // the exemplar's mean nearest-neighbour distance
    // Frames after the centre's a neighbourhood reaches: 0 = temporal-causal (group k is k
    // frames back); h >= 1 = temporal-non-causal for all-frame synthesis (Figure 3, bottom):
    // temporal = 2h + 1 groups covering the offsets -h .. +h.
    int ahead = 0;
};

// The time offset t(s') - t(s) of group k: causal 0, -1, -2, ...; non-causal 0, +1, -1, +2,
// -2, ... (group 0 is always the centre's own frame).
inline int time_offset(int k, const StParams& p) {
    if (p.ahead == 0) return -k;
    return k % 2 == 1 ? (k + 1) / 2 : -(k / 2);
}

struct StEntry {
    Vec3 offset;         // p(s') - p(s) (for past frames with the flow's displacement since added)
    double kappa = 1.0;  // Eq. 10 falloff of this entry about the centre
    int type = 0;
    int sample = -1;     // the sample s' (output: for the assignment; input: its sample index)
};

// One neighbourhood: entries of group k in [start[k], start[k + 1]).
struct StNeighbourhood {
    std::vector<StEntry> entries;
    std::array<int, max_temporal + 1> start{};
    int groups = 0;
};

// Eq. 10 (in squared-distance form so that sigma_p is a length: see docs/dynamic.md).
// `k`: the time offset in frames (its sign does not matter).
inline double falloff(const Vec3& offset, int k, const StParams& p) {
    if (p.inv_sigma_p2 == 0.0 && p.inv_sigma_t2 == 0.0) return 1.0;
    return std::exp(-squared_norm(offset) * p.inv_sigma_p2 - double(k) * double(k) * p.inv_sigma_t2);
}

// Sorts a gathered group by distance (then sample index, so that ties do not depend on the
// visiting order) and keeps the max_group nearest.
void finish_group(std::vector<StEntry>& entries, int begin);

}  // namespace tessera::dynamic
