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
//
// A minority type (under half of the exemplar) can fall short for another reason: growth
// packs it as random sequential adsorption does, and the exemplar's is packed denser. The
// stones of a two-class pattern (22 among 90 pebbles) grew at 0.17 per unit area against the
// exemplar's 0.19 (its interior) to 0.22 (the whole box), a share of 0.154 against 0.196, and
// no place was left where a stone's hard core held. Such a type's elements are inserted
// where its own stand kSqueeze of the hard core apart, the nearest pushed out.
//
// A packing (a type whose hard core is most of its spacing) can fall short of the exemplar's
// density for the same reason with no other type to take the room of: a dense random packing
// of spheres (packing fraction 0.53) grew at 0.79 of its density, jammed as adsorption jams
// (0.38). Before the shares are looked at, such a type, under 90% of the count its density
// asks of the region, gets its missing elements in the gaps between its own (probed around
// each of them), pushed in the same way.
#pragma once

#include <vector>

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Types whose exemplar share is under this are rare.
constexpr double kRareShare = 0.10;
// Single-sample types whose exemplar share is under this (a minority: the stones among
// pebbles) are completed too, their own elements pushed to make room (rare_types.cpp).
constexpr double kMinorityShare = 0.5;
// A rare type is completed when the call grew fewer than this share of its expected count.
constexpr double kRareShortfall = 0.90;
// A type is a packing when its hard core is at least this share of its mean spacing (random
// sequential adsorption jams at 0.83 in the plane, 0.90 in space; the spheres' exemplar is
// at 0.99, Poisson disks 0.84): short of its density, it is jammed, and gets its missing
// elements pushed in. Clustered and random patterns fall short for other reasons, and
// their gaps are theirs (the spatstat patterns: 0.16 to 0.54; the two-class pebbles 0.52).
constexpr double kPackedCore = 0.7;

// Whether type t is a packing (kPackedCore).
bool packed(const Grower::Impl& g, int t);

// What complete_rare_types did.
struct TypeCompletion {
    int inserted = 0;  // elements inserted
    int squeezed = 0;  // of them, of a minority type whose own elements were pushed
    int removed = 0;   // elements of other types removed where they went
    std::vector<char> completed;  // per type: whether elements of it were inserted
};

// For each rare type, and each minority type of single-sample elements, short of its share
// among elements [first, end) of `region`: inserts elements of it up to its expected count
// (the share times the call's count), farthest from the type's elements first, removing the
// unlocked elements of [first, end) of other types they overlap (no more of them than take
// about the room of the inserted element). A minority type's elements go where its own are
// kSqueeze of its hard core away or more, those of the call pushed out (by at most kMaxPush
// hard cores). A site whose element would leave the region, or overlap a locked element or
// one of a rare type, is passed over. First, each packing type (single-sample, not on a
// layer, at least kMinorityShare of the exemplar, its hard core at least kPackedCore of its
// spacing) short of kRareShortfall of its density's count in the region is completed the
// same way, up to that count, at points probed in the gaps between its own elements.
TypeCompletion complete_rare_types(Grower::Impl& g, int first, const Domain& region);

}  // namespace tessera::grow
