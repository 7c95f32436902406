// The paper's candidate choice (section IV): single-player Monte-Carlo tree search over
// which of a round's candidates become the horizon.
#pragma once

#include <vector>

#include "grow/generate.hpp"

namespace tessera::grow {

struct SearchReport {
    int playouts = 0;
    double best_score = 0.0;  // Eq. 4 per horizon element of the choice returned
};

// Chooses a subset of `candidates` (none closer to another than their hard core) and
// replaces `candidates` by it. The tree decides, candidate by candidate in order of fit,
// whether to take it; play-outs complete a choice at random until no candidate is left;
// nodes are selected by Eq. 5 and the best complete choice seen is returned (anytime).
SearchReport choose_by_tree_search(const Grower::Impl& g, std::vector<Candidate>& candidates);

}  // namespace tessera::grow
