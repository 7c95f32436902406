// One round of growth (grow/round.hpp).
#include "grow/round.hpp"

#include <algorithm>

#include "grow/generate.hpp"
#include "grow/mcts.hpp"
#include "grow/optimize.hpp"
#include "grow/vacancies.hpp"

namespace tessera::grow {

namespace {

// The tree search merges only candidates this close (a share of their hard core): the
// other conflicts are its decisions.
constexpr double kTreeSearchMerge = 0.5;
// Rounds a candidate dropped by the energy filter is proposed again.
constexpr int kRetries = 2;
// The rounds whose elements a candidate of a type short of its share may displace.
constexpr size_t kDisplaceRounds = 2;

// With a budget: the candidates nearest the origin, ties in their order.
void keep_nearest(std::vector<Candidate>& candidates, const Vec3& origin, int budget) {
    if (budget < 0 || static_cast<int>(candidates.size()) <= budget) return;
    std::stable_sort(candidates.begin(), candidates.end(), [&](const Candidate& a, const Candidate& b) {
        return dot(a.p - origin, a.p - origin) < dot(b.p - origin, b.p - origin);
    });
    candidates.resize(budget);
}

}  // namespace

int run_round(Grower::Impl& g, const RoundLimits& limits, GrowReport& report) {
    ++g.round;
    const size_t rounds = g.round_first.size();
    g.recent_first = rounds >= kDisplaceRounds
                         ? g.round_first[rounds - kDisplaceRounds]
                         : (rounds > 0 ? g.round_first[0] : static_cast<int>(g.out.size()));
    g.displaced = 0;
    std::vector<Candidate> candidates = propose(g, g.metric.patch_radius);
    report.candidates += static_cast<int>(candidates.size());
    for (Candidate& c : g.retry) candidates.push_back(c);  // after the fresh ones: they yield to them
    g.retry.clear();
    if (limits.region) report.outside += drop_outside(g, *limits.region, candidates);
    std::vector<Candidate> dropped;  // proposed again next round (their tries counted)
    if (g.options.choice == GrowChoice::patch) {
        report.merged += drop_overlapping(g, candidates, 1.0, limits.region, dropped);
    } else {
        report.merged += drop_overlapping(g, candidates, kTreeSearchMerge, limits.region, dropped);
        const size_t before = candidates.size();
        choose_by_tree_search(g, candidates);
        report.merged += static_cast<int>(before - candidates.size());
    }
    keep_nearest(candidates, limits.origin, limits.budget);
    const int first = add_candidates(g, candidates);
    double mean = 0.0;
    try {
        report.high_energy += drop_high_energy(g, first, g.options.energy_factor, mean, dropped);
    } catch (const Cancelled&) {  // the round's elements are not set up yet: it never happened
        g.drop_tail(first, std::vector<char>(g.out.size() - first, 0));
        throw;
    }
    for (const Candidate& c : dropped)
        if (c.tries <= kRetries) g.retry.push_back(c);
    const int added = static_cast<int>(g.out.size()) - first;
    report.last_made = added;
    if (added == 0) return -g.displaced;
    g.round_first.push_back(first);
    g.horizon.clear();
    for (int i = first; i < static_cast<int>(g.out.size()); ++i) {
        g.horizon.push_back(i);
        g.out[i].id = g.next_id++;
    }
    const OptimizeReport opt = optimize_round(g, limits.region);
    report.reassigned += opt.reassigned + opt.redistributed;
    report.energy = opt.unknowns > 0 ? opt.energy : mean;
    // The round two back is enclosed by now: its holes are filled.
    const size_t r = g.round_first.size();
    const int filled =
        r >= 3 ? fill_enclosed_holes(g, g.round_first[r - 3], g.round_first[r - 2], limits.region) : 0;
    report.filled += filled;
    report.added += added - g.displaced + filled;
    report.displaced += g.displaced;
    return added - g.displaced;
}

}  // namespace tessera::grow
