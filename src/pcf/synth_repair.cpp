// The final crowding repair of PCF synthesis (synth_repair.hpp).
#include "pcf/synth_repair.hpp"

#include <string>

#include "core/crowding_repair.hpp"
#include "core/parallel.hpp"

namespace tessera::pcf {

void repair_output(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out) {
    if (out.elements.empty()) return;
    const core::CrowdingBounds bounds(exemplar);
    core::CrowdingRepairOptions repair;
    repair.threads = core::resolve_threads(options.threads);
    const core::CrowdingRepairReport r = core::repair_crowding(out, domain, bounds, repair);
    RunStats& stats = out.stats;
    if (r.moved > 0)
        stats.notes.push_back("crowding repair: " + std::to_string(r.moved) + " moves in " + std::to_string(r.rounds) +
                              " rounds pushed elements closer than the exemplar's nearest-neighbour tail apart");
    if (r.bound_hit) {
        ++stats.solver_bound_hits;
        stats.notes.push_back("crowding repair stopped at its bound of " + std::to_string(repair.rounds) + " rounds with " +
                              std::to_string(r.remaining) + " elements still crowded");
    }
}

}  // namespace tessera::pcf
