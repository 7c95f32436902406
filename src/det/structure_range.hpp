// The distance over which an exemplar's elements are correlated, from its pair
// correlation: the default patch size of the initialization (section 4.1) must be at
// least about twice it, or patches cut every cluster, gap or lattice row apart and
// the copy loses the structure the solver then cannot rebuild from a neighbourhood
// of two spacings (docs/det.md, "Initialization").
#pragma once

#include "tessera/exemplar.hpp"

namespace tessera::det {

// How far the pair correlation g(r) of the exemplar's element centroids — pooled over
// all classes, and for every class pair — differs from 1 by more than its sampling
// noise: the end of the first stretch of r (up to r_limit) where it does, a stretch
// ending after max(2 spacings, r_limit / 10) without such a difference. Noise: the
// standard deviation of the kernel estimate for a Poisson pattern,
// sqrt(|W| / (S(r) n_a n_b h sqrt(pi))) (S(r) = 2 pi r or 4 pi r^2), times 3, and at
// least 0.1. Returns 0 for a Poisson-like pattern, about r_limit for a lattice.
// `spacing` is the mean nearest-neighbour distance.
// `threads`: workers of the pair correlation estimate (0 = all).
double structure_range(const Exemplar& exemplar, double spacing, double r_limit, int threads);

}  // namespace tessera::det
