// Contacts between the elements of an all-frame synthesis on a coarse motion: the detail
// motion laid on every thread and sheet is matched within each element (the grid
// neighbourhoods of topology_grid.hpp), so nothing in the matching stops the details of two
// neighbouring noodles from bending them into each other. After each assignment, samples of
// different elements are held apart (position-based, as the rest lengths are): no pair
// closer than half the distance the exemplar's elements keep, or, where the coarse motion
// already brings that pair closer, half its coarse distance. Details may interleave but never
// make elements touch or cross; the coarse motion the user gave is kept.
#pragma once

#include <algorithm>
#include <vector>

#include "core/parallel.hpp"
#include "tessera/animation.hpp"

namespace tessera::dynamic {

// The closest the samples of two different elements of `exemplar` come: the `quantile` of
// each sample-frame's distance to the nearest sample of another element, over all frames;
// 0 when the exemplar has one element.
double exemplar_contact_distance(const Animation& exemplar, double quantile);

struct ContactReport {
    int bound_hits = 0;       // frames whose sweeps stopped at the bound with pairs still too close
    double worst_gap = 0.0;   // the largest shortfall left, data units
    double first_gap = 0.0;   // the largest shortfall found before any push (how far the
                              // positions given were from holding the contacts)

    // Both reports' bound hits and their worst shortfalls.
    ContactReport& operator+=(const ContactReport& o) {
        bound_hits += o.bound_hits;
        worst_gap = std::max(worst_gap, o.worst_gap);
        first_gap = std::max(first_gap, o.first_gap);
        return *this;
    }
};

// Sweeps every frame (frames in parallel, each on its own: the same result for any thread
// count) until its largest shortfall is within `tolerance_gap`, at most `max_sweeps` times:
// `sweep(f, scratch)` runs one sweep of frame f and returns its largest shortfall; `Scratch`
// is one per worker. The frames' first and last shortfalls make the report.
template <class Scratch, class Sweep>
ContactReport sweep_frames(int frames, int threads, double tolerance_gap, int max_sweeps, const Sweep& sweep) {
    std::vector<double> left(frames, 0.0), found(frames, 0.0);
    core::parallel_for(frames, threads, [&](int begin, int end, int) {
        Scratch scratch;
        for (int f = begin; f < end; ++f) {
            double worst = sweep(f, scratch);
            found[f] = worst;
            for (int k = 1; k < max_sweeps && worst > tolerance_gap; ++k) worst = sweep(f, scratch);
            left[f] = worst;
        }
    });
    ContactReport report;
    for (int f = 0; f < frames; ++f) {
        report.bound_hits += left[f] > tolerance_gap;
        report.worst_gap = std::max(report.worst_gap, left[f]);
        report.first_gap = std::max(report.first_gap, found[f]);
    }
    return report;
}

// Pushes apart, frame by frame (frames in parallel; the same result for any thread count),
// every pair of samples of different elements (`element_of[s]`) closer than
// 0.5 x min(distance, their distance in `coarse`), half each way; sweeps until none is closer by
// more than `tolerance` x distance, at most `max_sweeps`. Positions frame-major, `samples`
// per frame, for both `positions` and `coarse`.
ContactReport keep_apart(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                         const std::vector<int>& element_of, int frames, int samples, int dimension,
                         double distance, double tolerance, int max_sweeps, int threads);

}  // namespace tessera::dynamic
