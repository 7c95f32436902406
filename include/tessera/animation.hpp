// tessera/animation.hpp — elements in space and time: a sequence of frames of the same
// elements (Dynamic Element Textures, section 3.1: every sample carries its time stamp,
// u(s) = (p(s), t(s)), Eq. 1).
//
// An Animation is the element structure of an Exemplar (types, elements with their stable
// ids, attributes, domain, and the sample layout: which samples make which element) plus
// the position of every sample in every frame. Every frame holds the same elements: the
// element set is fixed, only positions move. Frame-major flat storage, so that a frame is
// one contiguous run of sample positions and a sample's trail is a fixed stride.
//
// The topology of an element type (ElementType::topology) says how its samples hang
// together: none (particles, agents: any sample count, no order used), thread (1D: samples
// ordered by sample id, noodles, hair, branches) or sheet (2D: a grid of
// ElementType::sheet_columns columns, sample id = row x columns + column; paper, cloth).
#pragma once

#include <string>
#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera {

struct Animation {
    // The elements, types, attributes and domain. Its samples' positions are those of
    // frame 0 and their time stamps times[0]; positions of all frames are in `positions`.
    Exemplar structure;
    // Time stamp of each frame, strictly increasing; at least one frame.
    std::vector<double> times;
    // positions[f * sample_count() + s]: sample s (index into structure.samples) at frame f.
    std::vector<Vec3> positions;

    int frame_count() const { return static_cast<int>(times.size()); }
    int sample_count() const { return static_cast<int>(structure.samples.size()); }
    const Vec3& at(int frame, int sample) const { return positions[index(frame, sample)]; }
    Vec3& at(int frame, int sample) { return positions[index(frame, sample)]; }

    // Frame f as a static exemplar: the structure with the samples at frame f, their time
    // stamps times[f] and the element poses (centroids) recomputed.
    Exemplar frame(int f) const;
    // Appends a frame at time `time` with the given sample positions (sample_count() of them).
    void add_frame(double time, const std::vector<Vec3>& sample_positions);

    // Throws Error(input) naming `source` when the data break the model: the structure's own
    // invariants (Exemplar::validate), no frame, a positions array of the wrong size,
    // non-finite coordinates, time stamps that do not strictly increase, and element types
    // whose topology the elements do not have (check_topology).
    void validate(const std::string& source) const;

private:
    size_t index(int frame, int sample) const {
        return static_cast<size_t>(frame) * structure.samples.size() + static_cast<size_t>(sample);
    }
};

// A single static exemplar as a one-frame animation (its samples' time stamps ignored).
Animation animation_from_exemplar(const Exemplar& exemplar, double time = 0.0);

// Builds an animation from frames given as separate exemplars whose elements are matched by
// Element::id. Throws Error(input) naming `source` and the frame when a frame has a
// different element set (an id missing or extra), an element whose type or sample count
// differs from the first frame's, or time stamps (`times`, one per frame) that do not
// strictly increase.
Animation animation_from_frames(const std::vector<Exemplar>& frames, const std::vector<double>& times,
                                const std::string& source);

// The topology an element type has in effect: its ElementType::topology, or for automatic
// none when its elements have one sample and thread when they have several.
ElementTopology effective_topology(const Exemplar& data, int type);

// Throws Error(input) naming `source` and the type when a type's elements do not fit its
// topology: a sheet without sheet_columns >= 2 or whose sample count is not a multiple of
// them with at least 2 rows; a thread of fewer than 2 samples, or an element of a thread or
// sheet type whose sample ids are not exactly 0..n-1.
void check_topology(const Exemplar& data, const std::string& source);

// Per-frame sample velocities: (p(s, f) - p(s, f - 1)) / (t(f) - t(f - 1)) for f >= 1; frame
// 0 gets frame 1's (zero for a single frame). Same layout as Animation::positions.
std::vector<Vec3> sample_velocities(const Animation& animation);

}  // namespace tessera
