// Contacts between the elements of an all-frame synthesis on a coarse motion: the detail
// motion laid on every thread and sheet is matched within each element (the grid
// neighbourhoods of topology_grid.hpp), so nothing in the matching stops the details of two
// neighbouring noodles from bending them into each other. After each assignment, samples of
// different elements are held apart (position-based, as the rest lengths are): no pair
// closer than half the distance the exemplar's elements keep, or, where the coarse motion
// already brings that pair closer, half its coarse distance. Details may interleave but never
// make elements touch or cross; the coarse motion the user gave is kept.
#pragma once

#include <vector>

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
};

// Pushes apart, frame by frame (frames in parallel; the same result for any thread count),
// every pair of samples of different elements (`element_of[s]`) closer than
// 0.5 x min(distance, their distance in `coarse`), half each way; sweeps until none is closer by
// more than `tolerance` x distance, at most `max_sweeps`. Positions frame-major, `samples`
// per frame, for both `positions` and `coarse`.
ContactReport keep_apart(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                         const std::vector<int>& element_of, int frames, int samples, int dimension,
                         double distance, double tolerance, int max_sweeps, int threads);

}  // namespace tessera::dynamic
