// The pairing of an output neighbourhood with an input element's (Eq. 3 with DET's Eq. 1
// per pair), specialised for growth: every neighbour is one element (its centroid), so any
// output entry may pair with any input entry and no key ranges are needed. The result is
// det::match_greedy's, bit for bit; what differs is the inner loop, which reads the input
// neighbourhood as columns (InputElements::columns) and computes a whole row of pair
// costs in vector registers instead of one pair at a time through 48-byte entries.
#pragma once

#include <vector>

#include "det/model.hpp"

namespace tessera::grow {

struct InputElements;

// Reused buffers of the pairing (one per worker; no allocation once warm).
struct PairScratch {
    std::vector<double> rows;                  // row o: cost of output entry o with each input entry
    std::vector<std::pair<double, int>> heap;  // (cost of cheapest free partner, output entry)
    std::vector<int> best_input;
    std::vector<char> taken;
};

// Greedy pairing cost of output entries out[0, m) (single-sample entries, key 0, centred
// on the element being matched) against the first n neighbours of input element c: the
// cheapest pair first, each pair truncated at cap2, an unpaired output entry cap2. Stops
// and returns a value >= bound once that is certain; `partner` (may be null) gets the
// input neighbour index paired with each output entry, -1 for none.
double pair_greedy(const det::NeighborEntry* out, int m, const InputElements& in, int c, int n,
                   const det::Params& params, PairScratch& s, int* partner, double bound);

}  // namespace tessera::grow
