// Relative L2 difference between two pair correlation estimates, the single
// number `tessera metrics` reports for "how close is the output's PCF to the
// exemplar's". Curves are matched by class names (not indices) because an output
// may list its types in another order; a pair missing on one side counts as
// g = 0 there, so a class the output lost shows up as a large error.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera {
namespace {

using PairKey = std::pair<std::string, std::string>;

PairKey key_of(const PcfCurve& c) { return std::minmax(c.name_a, c.name_b); }

std::map<PairKey, const std::vector<double>*> curves_by_name(const PcfResult& result) {
    std::map<PairKey, const std::vector<double>*> out;
    for (const auto& c : result.curves) {
        if (c.g.size() != result.r.size())
            throw Error(ErrorKind::option, "pcf_relative_error: curve " + c.name_a + "-" + c.name_b +
                                               " has a different length than its r grid");
        out[key_of(c)] = &c.g;
    }
    return out;
}

}  // namespace

double pcf_relative_error(const PcfResult& reference, const PcfResult& other) {
    const auto& r = reference.r;
    bool same_grid = r.size() == other.r.size();
    for (size_t k = 0; same_grid && k < r.size(); ++k)
        same_grid = std::abs(r[k] - other.r[k]) <= 1e-9 * std::max(1.0, std::abs(r[k]));
    if (!same_grid) throw Error(ErrorKind::option, "pcf_relative_error: the two PCFs use different r grids");

    const auto ref = curves_by_name(reference), oth = curves_by_name(other);
    std::map<PairKey, int> keys;
    for (const auto& [k, v] : ref) keys[k] = 0;
    for (const auto& [k, v] : oth) keys[k] = 0;

    // sqrt(sum (g_ref - g_other)^2 / sum g_ref^2) over r >= h, pooled over pairs. From one
    // bandwidth on, not three: the shortest distances are where crowded and coincident
    // elements show, and the estimator is the same on both sides, so its bias there cancels.
    const double r_min = reference.bandwidth;
    double diff2 = 0.0, ref2 = 0.0;
    for (const auto& [key, unused] : keys) {
        const auto a = ref.find(key), b = oth.find(key);
        for (size_t k = 0; k < r.size(); ++k) {
            if (r[k] < r_min || r[k] <= 0.0) continue;
            const double ga = a == ref.end() ? 0.0 : (*a->second)[k];
            const double gb = b == oth.end() ? 0.0 : (*b->second)[k];
            if (!std::isfinite(ga) || !std::isfinite(gb)) continue;
            diff2 += (ga - gb) * (ga - gb);
            ref2 += ga * ga;
        }
    }
    if (ref2 > 0.0) return std::sqrt(diff2 / ref2);
    return diff2 > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

PcfResult pair_correlation_on_grid_of(const Exemplar& points, const PcfResult& grid) {
    PcfOptions same;
    same.r_max = grid.r.empty() ? 0.0 : grid.r.back();
    same.bandwidth = grid.bandwidth;
    same.bins = static_cast<int>(grid.r.size());
    return pair_correlation(points, same);
}

double pcf_relative_error(const Exemplar& exemplar, const Exemplar& output, const PcfOptions& options) {
    const PcfResult reference = pair_correlation(exemplar, options);
    return pcf_relative_error(reference, pair_correlation_on_grid_of(output, reference));
}

}  // namespace tessera
