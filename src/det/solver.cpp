// Discrete element texture synthesis (Pseudocode 1): initialize by patch copy, then
// iterate search and assignment, then the final passes; a one-shot call on DetSession
// (include/tessera/det_session.hpp, src/det/session.cpp), which holds the steps.
#include "core/run_clock.hpp"
#include "det/session_state.hpp"
#include "det/session_steps.hpp"
#include "tessera/det.hpp"
#include "tessera/det_session.hpp"
#include "tessera/error.hpp"

namespace tessera {

Arrangement synthesize_det(const Exemplar& exemplar, const Domain& domain, const DetOptions& options,
                           const Progress& progress) {
    const auto t0 = core::Clock::now();
    core::report(progress, {"init", -1, options.iterations, 0.0, 0.0});
    DetSession session(exemplar, options);
    session.impl().t0 = t0;  // the index build counts as the run's
    session.set_progress(progress);
    session.set_domain(domain);
    DetSession::Impl& s = session.impl();
    // Shares of the run for the progress fraction, by what each phase costs typically.
    s.span_lo = 0.02, s.span_hi = 0.15;
    session.initialize(domain);
    s.span_lo = 0.15, s.span_hi = 0.85;
    session.iterate(options.iterations);
    s.span_lo = 0.85, s.span_hi = 0.99;
    session.finish();
    Arrangement out = session.take_arrangement();
    det::number_compactly(out);  // a new arrangement: ids 0..n-1 in element order
    out.stats.total_seconds = core::seconds_since(t0);
    core::report(progress, {"done", options.iterations, options.iterations, out.stats.final_energy,
                            out.stats.total_seconds, 1.0});
    return out;
}

}  // namespace tessera
