// dynamic/graph_nodes.cpp — the nodes, edge weights and immediate neighbours of graph synthesis.
#include "dynamic/graph_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace tessera::dynamic {

namespace {

constexpr double infinite = std::numeric_limits<double>::infinity();

// The k nearest nodes of `a` among `pool` (same type, not a), ties by sample index so that
// the order never depends on the visiting order.
std::vector<int> k_nearest(const NeighbourhoodGraph& g, int a, int k, const std::vector<int>& pool) {
    std::vector<std::pair<double, int>> found;
    for (int b : pool)
        if (b != a && std::isfinite(g.weight(a, b))) found.emplace_back(g.weight(a, b), b);
    const size_t keep = std::min(found.size(), static_cast<size_t>(k));
    std::partial_sort(found.begin(), found.begin() + static_cast<long>(keep), found.end());
    std::vector<int> out(keep);
    for (size_t i = 0; i < keep; ++i) out[i] = found[i].second;
    return out;
}

}  // namespace

StNeighbourhood spatial_neighbourhood(const InputFrames& frames, int sample, double radius) {
    StNeighbourhood n;
    const int id = frames.id(sample, 0);
    const StEntry* e = frames.entries(id);
    const int count = frames.group_start(id)[1];
    for (int i = 0; i < count && squared_norm(e[i].offset) <= radius * radius; ++i) n.entries.push_back(e[i]);
    n.groups = 1;
    n.start.fill(static_cast<int>(n.entries.size()));
    n.start[0] = 0;
    return n;
}

double edge_weight(const InputFrames& frames, const std::vector<StNeighbourhood>& own, int a, int b,
                   const StParams& params, MetricScratch& scratch) {
    if (frames.type(a) != frames.type(b)) return infinite;
    const double ab = st_distance(own[a], frames.entries(b), frames.group_start(b), params, scratch, nullptr, infinite);
    const double ba = st_distance(own[b], frames.entries(a), frames.group_start(a), params, scratch, nullptr, infinite);
    return 0.5 * (ab + ba);
}

// Every sample when they are few enough; otherwise, per type, the samples first in an order
// keyed by the seed, in proportion to the type's share (at least 2, so that it has a path).
void NeighbourhoodGraph::choose_pool(const InputFrames& frames, int max_nodes, std::uint64_t seed) {
    column_.assign(samples_, -1);
    if (samples_ <= max_nodes) {
        for (int s = 0; s < samples_; ++s) pool_.push_back(s);
    } else {
        const core::KeyedRng rng(seed, core::Purpose::dynamic_graph, 0);
        int types = 0;
        for (int s = 0; s < samples_; ++s) types = std::max(types, frames.type(s) + 1);
        for (int t = 0; t < types; ++t) {
            std::vector<std::pair<std::uint64_t, int>> order;
            for (int s = 0; s < samples_; ++s)
                if (frames.type(s) == t) order.emplace_back(rng.bits(static_cast<std::uint64_t>(s)), s);
            const auto quota = std::min(order.size(), std::max<size_t>(2, order.size() * max_nodes / samples_));
            std::partial_sort(order.begin(), order.begin() + static_cast<long>(quota), order.end());
            for (size_t i = 0; i < quota; ++i) pool_.push_back(order[i].second);
        }
        std::sort(pool_.begin(), pool_.end());
    }
    for (size_t c = 0; c < pool_.size(); ++c) column_[pool_[c]] = static_cast<int>(c);
}

NeighbourhoodGraph::NeighbourhoodGraph(const InputFrames& frames, const StParams& params, int max_nodes, int k,
                                       std::uint64_t seed, int threads)
    : samples_(frames.size()) {
    choose_pool(frames, max_nodes, seed);
    std::vector<StNeighbourhood> own(samples_);
    for (int s = 0; s < samples_; ++s) own[s] = spatial_neighbourhood(frames, s, params.radius);
    const size_t columns = pool_.size();
    d_.assign(static_cast<size_t>(samples_) * columns, infinite);
    std::vector<MetricScratch> scratch(core::resolve_threads(threads));
    // Rows in parallel, each writing its own; a pair of two nodes is computed from both rows,
    // twice, which keeps every row independent of the others.
    core::parallel_for(
        samples_, threads,
        [&](int begin, int end, int thread) {
            for (int a = begin; a < end; ++a)
                for (size_t c = 0; c < columns; ++c)
                    d_[a * columns + c] = edge_weight(frames, own, a, pool_[c], params, scratch[thread]);
        },
        4);
    for (double w : d_)
        if (std::isfinite(w)) delta_ = std::max(delta_, w);
    nearest_.resize(samples_);
    core::parallel_for(samples_, threads, [&](int begin, int end, int) {
        for (int a = begin; a < end; ++a) nearest_[a] = k_nearest(*this, a, k, pool_);
    });
}

NeighbourhoodGraph::NeighbourhoodGraph(int n, std::vector<double> weights, int k, int threads)
    : samples_(n), d_(std::move(weights)) {
    column_.resize(n);
    for (int s = 0; s < n; ++s) pool_.push_back(s), column_[s] = s;
    for (double w : d_)
        if (std::isfinite(w)) delta_ = std::max(delta_, w);
    nearest_.resize(n);
    core::parallel_for(n, threads, [&](int begin, int end, int) {
        for (int a = begin; a < end; ++a) nearest_[a] = k_nearest(*this, a, k, pool_);
    });
}

}  // namespace tessera::dynamic
