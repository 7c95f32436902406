// The options of the standard pair correlation estimate (PcfOptions, tessera/metrics.hpp),
// one row each: `tessera analyze --standard-pcf` and `tessera metrics` make their flags from
// this table, Python's pair_correlation and metrics their keywords, and pair_correlation
// checks a struct against it.
#include "core/option_rows.hpp"
#include "tessera/metrics.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = PcfOptions;

// More values of r than any plot or comparison needs: a typo, not a request.
constexpr int kMaxBins = 1'000'000;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(number_row<O>(
        "r_max", "Largest r of the pair correlation; 0 = automatic (5 x the mean nearest-neighbour distance).",
        [](auto& o) -> auto& { return o.r_max; }, at_least(0)));
    t.push_back(number_row<O>(
        "bandwidth", "Standard deviation of the Gaussian kernel; 0 = automatic (r_max / 40).",
        [](auto& o) -> auto& { return o.bandwidth; }, at_least(0)));
    OptionSpec<O> bins = integer_row<O>(
        "bins", "Number of values of r, from 0 to r_max; 0 = automatic (101).",
        [](auto& o) -> auto& { return o.bins; }, between(2, kMaxBins));
    bins.zero_is_automatic = true;
    t.push_back(bins);
    return t;
}

}  // namespace

const OptionTable<PcfOptions>& pair_correlation_option_table() {
    static const OptionTable<PcfOptions> table = make_table();
    return table;
}

}  // namespace tessera
