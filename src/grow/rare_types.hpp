// Rare types brought back to their share (grow/rare_types.cpp).
//
// Rounds propose an element of type t only from horizon matches whose input patch holds one.
// A type the exemplar holds few of sits in few input neighbourhoods, the matches that hold
// one are rarely the best, and the candidates they do propose mostly land on elements other
// patches already put there: the membrane's channel proteins (3 of 177 elements) grew at 55%
// to 76% of their share, and the paper's own membrane lost its small molecules or
// overproduced them. Once a region is covered, a rare type clearly short of its share in
// what the call grew gets its missing elements where its own elements are farthest apart,
// each taking the place of the call's unlocked elements it overlaps.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Types whose exemplar share is under this are rare.
constexpr double kRareShare = 0.10;
// A rare type is completed when the call grew fewer than this share of its expected count.
constexpr double kRareShortfall = 0.90;

// For each rare type short of its share among elements [first, end) of `region`: inserts
// elements of it up to its expected count (the share times the call's count), farthest from
// the type's elements first, removing the unlocked elements of [first, end) of common types
// they overlap (no more of them than take about the room of the inserted element). A site
// whose element would leave the region, or overlap a locked element or one of a rare type,
// is passed over. Returns how many were inserted; `removed` gets how many were removed.
int complete_rare_types(Grower::Impl& g, int first, const Domain& region, int& removed);

}  // namespace tessera::grow
