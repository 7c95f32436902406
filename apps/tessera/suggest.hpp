// apps/tessera/suggest.hpp — "did you mean ...?" for a mistyped subcommand or option:
// the candidate closest to what was typed, by edit distance (a swap of two neighbouring
// letters counts as one edit) or because one is a prefix of the other ("synthesize" for
// "synth", "--iteration" for "--iterations"), when it is close enough to be what was meant.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tessera_cli {

// Edits (insertions, deletions, substitutions, swaps of neighbours) from `a` to `b`.
int edit_distance(const std::string& a, const std::string& b);

// The candidate that `typed` most likely meant, or nullopt when none is close: at most
// 1 + n/4 edits away (n = the length of `typed` without leading dashes), or a prefix of
// it or it of the candidate with at least 3 letters in common. Ties go to the earlier
// candidate. A single letter gets no suggestion.
std::optional<std::string> closest_match(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace tessera_cli
