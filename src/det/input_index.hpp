// Building the solver's parameters and the precomputed exemplar index.
#pragma once

#include "det/model.hpp"

namespace tessera::det {

// Resolves automatic options against the exemplar; throws Error(option) for invalid values.
Params resolve_params(const Exemplar& exemplar, const DetOptions& options);

// Builds neighbourhoods, key lists and the lookup grid, and, when k > 0, the
// k-coherence similarity sets (section 4.2) by brute-force matching of every
// pair of same-key input samples, on `threads` threads.
InputIndex build_input_index(const Exemplar& exemplar, const Params& params, int k, int threads);

// Gathers the neighbourhood of position `center` among `positions` within
// `radius` (excluding sample `self`), sorted by distance then index, into `out`.
// At most `max_count` nearest entries are kept.
void gather_neighbors(const core::SpatialGrid& grid, const std::vector<Vec3>& positions, const Vec3& center,
                      int self, double radius, int dimension, const std::vector<int>& key,
                      const std::vector<int>& type, const std::vector<int>& element,
                      const std::vector<double>& element_radius, std::vector<NeighborEntry>& out,
                      std::vector<std::pair<double, int>>& scratch, int max_count);

// Largest neighbourhood kept per sample; guards against a collapsed output.
inline constexpr int max_neighbors = 256;

}  // namespace tessera::det
