// The state a DetSession keeps between calls (include/tessera/det_session.hpp): what is
// prepared once from the exemplar and options, and the output being synthesized. Growth
// (src/grow) works on it directly.
#pragma once

#include <chrono>
#include <optional>

#include "core/crowding_repair.hpp"
#include "core/interrupt.hpp"
#include "det/input_index.hpp"
#include "det/model.hpp"
#include "det/physics_guard.hpp"
#include "det/search.hpp"
#include "det/vacancies.hpp"
#include "tessera/det_session.hpp"

namespace tessera {

struct DetSession::Impl {
    Impl(const Exemplar& exemplar, const DetOptions& options);

    // Prepared once.
    Exemplar exemplar;
    DetOptions options;
    det::Params params;
    int threads = 1;
    det::InputIndex index;          // points into `exemplar` (the Impl never moves)
    core::CrowdingBounds tails;     // the exemplar's close-distance tails (core/crowding_repair.hpp)
    det::VacancySettings vacancies; // its largest hole (det/vacancies.hpp)
    det::SearchSettings search;

    // The output.
    det::OutputState state;
    Domain domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    bool has_domain = false;
    std::uint64_t next_id = 0;      // id of the next element made
    int rounds = 0;                 // iterations run so far: keys the vacancy filling's draws
    std::optional<det::PhysicsGuard> guard;
    bool physics_measured = false;

    Progress progress;
    ProgressEvent last_event;  // re-sent by `interrupt` during a long step
    core::Interrupt interrupt{[this] { resend_last_event(); }};
    // The share of the caller's whole run that the current call spans: a stage's own
    // fraction maps into it (synthesize_det sets it per phase; a lone call spans 0 to 1).
    double span_lo = 0.0, span_hi = 1.0;
    double last_fraction = 0.0;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();

    // Sends a progress event (Cancelled if the callback says stop).
    void report(const char* stage, int index, int count, double energy = 0.0);
    void resend_last_event();
    // One search + assignment iteration over the held arrangement, with its sub-steps. A
    // region's sub-problem (whole = false) has no physics step and fills no holes: its
    // domain reaches beyond its elements.
    double iterate_once(bool whole = true);
};

}  // namespace tessera
