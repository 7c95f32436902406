// Generation (section IV): candidates from the partial pair assignments of the horizon,
// and the filters that thin them.
#pragma once

#include <vector>

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Element counts per type of the output against the exemplar's shares: what the type
// balance of the overlap filter (displacement, redistribution) and of the reassignment
// steps (section V.B-C) weighs.
class TypeBalance {
public:
    explicit TypeBalance(const Grower::Impl& g);
    void add(int t) { ++count_[t], ++total_; }
    void remove(int t) { --count_[t], --total_; }
    // Type t clearly short of its share (below kMargin of it).
    bool is_short(int t) const { return share(t) < kMargin * share_[t]; }
    // How far type t is below its share, relative to it (negative when over).
    double deficit(int t) const { return share_[t] > 0.0 ? (share_[t] - share(t)) / share_[t] : -1.0; }
    // Type t over its share.
    bool over(int t) const { return share(t) > share_[t]; }
    // Type t is short of its share, and every blocking element is recent, unlocked,
    // and of a type over its share (at most kMaxDisplaced of them).
    bool may_displace(int t, const std::vector<int>& blocking) const;
    // When type u is over its share: the type most short of its share (below the margin), else -1.
    int short_type(int u) const;

private:
    static constexpr int kMaxDisplaced = 4;
    // Only a type clearly short of its share displaces others (no back and forth).
    static constexpr double kMargin = 0.97;
    double share(int t) const { return total_ > 0 ? static_cast<double>(count_[t]) / total_ : 0.0; }
    const Grower::Impl& g_;
    std::vector<int> count_;
    std::vector<double> share_;
    int total_ = 0;
};

// For each horizon element h: its best input element e (also stored as its match), then
// the input neighbours e' of e within `extent` that the partial pair assignment leaves
// without an output partner closer than c, as candidates at p(h) + o(h)(p(e') - p(e)).
// In horizon order; parallel over the horizon.
std::vector<Candidate> propose(Grower::Impl& g, double extent);

// Drops candidates with a sample outside `region`; returns how many.
int drop_outside(const Grower::Impl& g, const Domain& region, std::vector<Candidate>& candidates);

// The overlap filter: candidates taken best fit first, each dropped when an existing
// element lies closer than the hard-core distance of their types, or an already taken
// candidate closer than `merge` times it (1: the patch choice; the tree search merges only
// near-duplicates and resolves the other conflicts itself). A candidate of a type short of
// its share in the output may displace last round's elements of types over theirs (they are
// removed). A candidate that would break the count ceiling (Impl::crowd) is dropped into
// `over_ceiling` (its tries counted): the crowding its neighbourhood shows at the horizon
// may be gone a round later, once the elements around it have settled. Returns how many
// candidates were dropped.
int drop_overlapping(Grower::Impl& g, std::vector<Candidate>& candidates, double merge, const Domain* region,
                     std::vector<Candidate>& over_ceiling);

// The energy filter, on candidates already added as elements [first, end): each one's best
// neighbourhood energy (per neighbour) against the round's mean; those above t times it
// are removed. Returns how many, and the mean energy of those kept in `mean`.
// Candidates dropped are appended to `dropped`.
int drop_high_energy(Grower::Impl& g, int first, double t, double& mean, std::vector<Candidate>& dropped);

// Adds candidates as elements of round g.round (ids assigned later); returns the first index.
int add_candidates(Grower::Impl& g, const std::vector<Candidate>& candidates);

}  // namespace tessera::grow
