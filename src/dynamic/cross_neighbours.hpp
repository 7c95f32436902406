// The samples of other elements in a thread's or a sheet's neighbourhood (Dynamic Element
// Textures, section 3.3: "These topological constraints precede the Hungarian algorithm
// above, which applies only to sample pairs without any topological constraints").
//
// All-frame synthesis on a coarse motion works on details (the offset of each sample from its
// coarse place, in the coarse geometry's local frame): the coarse motion is given, so what a
// neighbourhood compares of another element's sample s' is its detail relative to the
// centre's, u(s') - u(s) of Eq. 2 with u the detail, both in the centre's frame. The pairs
// come from the Hungarian algorithm on the coarse places (the neighbour on the left pairs
// with the exemplar's neighbour on the left); Eq. 4 then adds the squared differences of the
// paired relative details, an unpaired entry costing the cap. So neighbouring noodles whose
// kinks run together in the exemplar run together in the output: the grid part of the
// neighbourhood alone matches each element's detail within the element.
#pragma once

#include <vector>

#include "core/hungarian.hpp"
#include "dynamic/detail_field.hpp"
#include "dynamic/local_frames.hpp"

namespace tessera::dynamic {

struct CrossEntry {
    int sample = -1;  // the other element's sample
    Vec3 place;       // its coarse offset from the centre, in the centre's local frame
};

// Per sample-frame (frame-major, like Animation::positions): the samples of other elements
// within `radius` of its coarse place at the same frame, nearest first (ties by index), at
// most kMax.
class CrossNeighbours {
public:
    static constexpr int kMax = 6;

    CrossNeighbours() = default;
    CrossNeighbours(const std::vector<Vec3>& coarse, const std::vector<LocalFrame>& frames,
                    const std::vector<int>& element_of, int frame_count, double radius, int dimension, int threads);

    int count(int k) const { return count_.empty() ? 0 : count_[k]; }
    const CrossEntry* entries(int k) const { return entries_.data() + static_cast<size_t>(k) * kMax; }

private:
    std::vector<CrossEntry> entries_;
    std::vector<int> count_;
};

// The cross part of the detail neighbourhoods of an output and its exemplar.
struct CrossTerm {
    const CrossNeighbours* out = nullptr;
    const CrossNeighbours* in = nullptr;
    const std::vector<LocalFrame>* out_frames = nullptr;  // the coarse motion's, per sample-frame
    const std::vector<LocalFrame>* in_frames = nullptr;   // the exemplar's coarse motion's
    double weight = 1.0;  // of each pair, against a grid entry's 1
    bool active() const { return out && in && weight > 0.0; }
};

// Scratch of one worker.
struct CrossScratch {
    std::vector<double> cost;
    std::vector<int> column;
    core::HungarianScratch hungarian;
};

// Eq. 4 over the cross entries of output sample-frame (s, f) and input (j, g): pairs by the
// Hungarian algorithm on the coarse places (an entry may stay unpaired at the cap), then the
// weighted squared differences of the paired relative details plus cap2 per unpaired entry
// on either side. With `partner`, writes the input sample paired with each output entry
// (-1 = unpaired).
double cross_distance(const CrossTerm& term, const DetailField& out, int f, int s, const DetailField& in, int g,
                      int j, double cap2, CrossScratch& scratch, int* partner = nullptr);

// The reach of the cross entries: 1.5 x the median, over the sample-frames of `coarse`
// (frame-major), of the distance to the nearest sample of another element: about the next
// element's nearest samples and their neighbours along it. 0 when there is one element.
double cross_radius(const std::vector<Vec3>& coarse, const std::vector<int>& element_of, int frame_count,
                    int dimension);

// u(s') - u(s) of Eq. 2 for details: the detail of sample b relative to that of sample a at
// sample-frame indices ka, kb of one field, in a's local frame.
Vec3 relative_detail(const DetailField& field, const std::vector<LocalFrame>& frames, int ka, int kb);

}  // namespace tessera::dynamic
