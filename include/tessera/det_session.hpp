// tessera/det_session.hpp — the neighbourhood method (Discrete Element Textures) as an
// object that keeps its state between calls.
//
// synthesize_det is one pass: build the input index, initialize, iterate, repair. Growth,
// tiled worlds, brushing and frame-by-frame animation all need the same engine to work
// next to elements that already exist and must not move: "iterate this region, the rest
// fixed". A DetSession is built once from an exemplar and options (the input index, the
// similarity sets, the neighbourhood radius and the exemplar's bounds of crowding and holes
// are computed there) and holds one output arrangement that its calls change.
//
// Locked elements (Element::locked) are never moved, retyped, renumbered or removed by any
// call: they leave every call bit-identical. Elements outside the region of a call are
// fixed for that call (they take part as neighbours only).
//
// Not thread-safe: one thread at a time per session (sessions are independent).
#pragma once

#include <memory>

#include "tessera/det.hpp"
#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/progress.hpp"

namespace tessera {

class DetSession {
public:
    // Validates the exemplar and options (Error(input), Error(option)) and prepares the
    // input index. The session keeps its own copy of the exemplar.
    DetSession(const Exemplar& exemplar, const DetOptions& options = {});
    ~DetSession();
    DetSession(DetSession&&) noexcept;
    DetSession& operator=(DetSession&&) noexcept;
    DetSession(const DetSession&) = delete;
    DetSession& operator=(const DetSession&) = delete;

    // Progress of the calls that follow (stages "patches", "fill", "iteration", "relax",
    // "repair", "settle"); returning false cancels the running call: Cancelled is thrown and
    // the arrangement is valid (every element whole, locked ones untouched) but only partly
    // through the call.
    void set_progress(Progress progress);

    // Replaces the held arrangement by `existing`, whose types are matched to the exemplar's
    // by name (Error(input) naming a type the exemplar does not have, or a sample count that
    // differs from the exemplar's for that type). Its domain becomes the session's domain.
    void set_arrangement(const Arrangement& existing);
    // The held arrangement (its domain is the session's output domain).
    const Arrangement& arrangement() const;
    Arrangement take_arrangement();

    // The output domain: boundary terms and the final passes keep elements inside it.
    // initialize() of an empty arrangement sets it to its region; set_domain changes it
    // (Error(domain) for a dimension other than the exemplar's).
    void set_domain(const Domain& domain);
    const Domain& domain() const;

    // Patch-copy initialization of `region` (section 4.1), then the holes filled and the
    // types over their count thinned. With an empty arrangement this is the first step of
    // synthesize_det and `region` becomes the domain. With elements already held, copied
    // elements closer to an existing one than the exemplar's hard-core distance for that
    // pair of types are not kept, and existing elements are untouched. Returns the number
    // of elements added.
    int initialize(const Domain& region);

    // Search + assignment iterations (section 4.2, 4.3) with the sub-steps that keep the
    // crowding and hole bounds. iterate(n) moves every unlocked element; iterate(region, n)
    // only the unlocked elements whose centre lies in `region`, with the elements within
    // two neighbourhood radii around them as fixed neighbours: its cost is the region's,
    // not the arrangement's. Returns the energy (Eq. 2) of the last search.
    double iterate(int iterations);
    double iterate(const Domain& region, int iterations);

    // The final passes of synthesize_det over the whole arrangement: pair-correlation
    // relaxation, elements moved inside the domain, crowding repair and hole filling,
    // physics settling, and the energy of the result (stats.final_energy).
    void finish();

    // The resolved neighbourhood radius (DetOptions::radius or the automatic one).
    double radius() const;

    struct Impl;  // src/det/session_state.hpp; public so that growth (src/grow) can reach it
    Impl& impl() { return *impl_; }

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tessera
