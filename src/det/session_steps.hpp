// The steps a DetSession runs around its search and assignment (src/det/session.cpp):
// taking an initialization or an existing arrangement in, the sub-steps that keep the
// exemplar's bounds after every iteration, and the final passes.
#pragma once

#include "det/init.hpp"
#include "det/session_state.hpp"

namespace tessera::det {

// The physics options of a run: gravity along the method's axis unless given.
PhysicsOptions physics_options(const DetOptions& options, const Params& params);

// An empty session takes the initialization as its output; `region` is its domain.
void adopt_initialization(DetSession::Impl& s, InitResult init, const Domain& region);
// Appends the (already filtered) initialized elements to the session's output.
void append_elements(OutputState& state, InitResult& init);
// Replaces the session's output by an existing arrangement (types matched by name).
void adopt_arrangement(DetSession::Impl& s, const Arrangement& existing);

// The sub-steps that keep the output's holes and close pairs within the exemplar's:
// vacancies filled, types over their count thinned where crowded, pairs pushed apart.
// `round` keys the random draws. With fill_holes false only the crowding is repaired
// (a region's sub-problem, whose domain is wider than its elements).
core::CrowdingRepairReport keep_bounds(DetSession::Impl& s, int round, bool fill_holes = true);

// The final passes of synthesize_det (DetSession::finish).
void finish(DetSession::Impl& s);

// Gives the elements made since the last call (id kNewElementId) the ids next_id, next_id + 1
// ... in element order: the ids of existing elements never change.
void number_new_elements(Arrangement& out, std::uint64_t& next_id);
// Numbers all elements 0..n-1 in element order (synthesize_det's output, nothing locked).
void number_compactly(Arrangement& out);

}  // namespace tessera::det
