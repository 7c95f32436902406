// dynamic/graph_path.cpp — Eq. 13 and the simulated annealing of a motion path.
#include "dynamic/graph_path.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"

namespace tessera::dynamic {

double path_energy(const NeighbourhoodGraph& graph, const std::vector<int>& nodes, double alpha) {
    const int n = static_cast<int>(nodes.size()) - 1;
    if (n < 1) return 0.0;
    const double delta = graph.delta() > 0.0 ? graph.delta() : 1.0;
    double steps = 0.0;
    for (int i = 0; i < n; ++i) steps += graph.weight(nodes[i], nodes[i + 1]);
    // Ordered pairs (i, j), i != j: twice the unordered ones; i == j adds nothing.
    double pairs = 0.0;
    for (int i = 0; i <= n; ++i)
        for (int j = i + 1; j <= n; ++j) pairs += 2.0 * graph.weight(nodes[i], nodes[j]);
    return steps / delta + alpha * (1.0 - pairs / (delta * n * (n + 1)));  // Eq. 13
}

namespace {

// Draws of new paths from a path: replace an interior node, insert one, remove one. At the
// length bounds insert and remove become a relocation (remove one node, insert another), so
// that a fixed n (min_steps = max_steps) still has every move. A new node is an immediate
// neighbour of one of its path neighbours: most of the complete graph's nodes are far from
// both, and proposing them would waste the iterations.
class Proposer {
public:
    Proposer(const NeighbourhoodGraph& graph, const core::KeyedRng& rng, int min_steps, int max_steps)
        : graph_(graph), rng_(rng), min_steps_(min_steps), max_steps_(max_steps) {}

    // False when the draw gave no valid path (a node already on it).
    bool propose(const std::vector<int>& path, std::uint64_t& counter, std::vector<int>& next) const {
        next = path;
        int kind = static_cast<int>(rng_.below(counter++, 3));  // 0 replace, 1 insert, 2 remove
        if (path.size() == 2) kind = 1;                          // no interior node yet
        if (kind == 0) return replace(next, counter);
        if (kind == 2 || steps(next) >= max_steps_) remove(next, counter);
        if (kind == 1 || steps(next) < min_steps_) return insert(next, counter);
        return true;
    }

    // Inserts a node anywhere (the start path's growth); false when the draw repeats a node.
    bool insert(std::vector<int>& path, std::uint64_t& counter) const {
        const int i = 1 + static_cast<int>(rng_.below(counter++, path.size() - 1));  // before path[i]
        const int node = draw_near(path[rng_.below(counter++, 2) == 0 ? i - 1 : i], counter);
        if (node < 0 || on(path, node)) return false;
        path.insert(path.begin() + i, node);
        return true;
    }

private:
    static int steps(const std::vector<int>& path) { return static_cast<int>(path.size()) - 1; }
    static bool on(const std::vector<int>& path, int node) {
        return std::find(path.begin(), path.end(), node) != path.end();
    }
    int draw_near(int anchor, std::uint64_t& counter) const {
        const std::vector<int>& choices = graph_.nearest(anchor);
        return choices.empty() ? -1 : choices[rng_.below(counter++, choices.size())];
    }
    bool replace(std::vector<int>& path, std::uint64_t& counter) const {
        const int i = 1 + static_cast<int>(rng_.below(counter++, path.size() - 2));
        const int node = draw_near(path[rng_.below(counter++, 2) == 0 ? i - 1 : i + 1], counter);
        if (node < 0 || on(path, node)) return false;
        path[i] = node;
        return true;
    }
    void remove(std::vector<int>& path, std::uint64_t& counter) const {
        if (path.size() > 2) path.erase(path.begin() + 1 + static_cast<long>(rng_.below(counter++, path.size() - 2)));
    }

    const NeighbourhoodGraph& graph_;
    const core::KeyedRng& rng_;
    int min_steps_, max_steps_;
};

// The start path: the direct one grown by random insertions to min_steps (bounded attempts:
// a type with few nodes may not have that many; the path is then as long as it could be).
std::vector<int> start_path(int a, int b, const Proposer& proposer, int min_steps, std::uint64_t& counter) {
    std::vector<int> path{a, b};
    for (int attempt = 0; attempt < 64 * min_steps && static_cast<int>(path.size()) - 1 < min_steps; ++attempt)
        proposer.insert(path, counter);
    return path;
}

}  // namespace

MotionPath anneal_path(const NeighbourhoodGraph& graph, int a, const AnnealSettings& settings) {
    MotionPath result;
    const int b = graph.far_neighbour(a);
    if (b < 0) {
        result.nodes = {a};
        return result;
    }
    const core::KeyedRng rng(settings.seed, core::Purpose::dynamic_graph, 1, static_cast<std::uint64_t>(a));
    std::uint64_t counter = 0;
    result.direct_energy = path_energy(graph, {a, b}, settings.alpha);
    const Proposer grow(graph, rng, 1, settings.max_steps);
    std::vector<int> current = start_path(a, b, grow, settings.min_steps, counter), next;
    const int min_steps = std::min(settings.min_steps, static_cast<int>(current.size()) - 1);
    const Proposer proposer(graph, rng, min_steps, settings.max_steps);
    double energy = path_energy(graph, current, settings.alpha);
    result.nodes = current, result.energy = energy;
    if (settings.max_steps < 2) return result;  // the direct path is the only one
    // Temperatures on the scale of one step: a move changes the energy by about that much.
    const double delta = graph.delta() > 0.0 ? graph.delta() : 1.0;
    const double t0 = std::max(0.5 * graph.weight(a, b) / delta, 1e-6);
    const double cooling = std::log(1e-3);
    const int patience = std::max(25, settings.iterations / 8);
    int last_accepted = 0;
    for (int it = 0; it < settings.iterations; ++it) {
        if (it - last_accepted > patience) return result;  // frozen
        const double progress = settings.iterations > 1 ? double(it) / (settings.iterations - 1) : 1.0;
        const double temperature = t0 * std::exp(cooling * progress);  // geometric cooling
        if (!proposer.propose(current, counter, next)) continue;
        const double e = path_energy(graph, next, settings.alpha);
        const double u = rng.uniform(counter++);
        if (e > energy && u >= std::exp(-(e - energy) / temperature)) continue;  // Metropolis
        current.swap(next);
        energy = e;
        last_accepted = it;
        if (energy < result.energy) result.nodes = current, result.energy = energy;
    }
    result.at_bound = settings.iterations - last_accepted <= patience;
    return result;
}

MotionPath chained_path(const NeighbourhoodGraph& graph, int a, const AnnealSettings& settings, int chains) {
    MotionPath chain = anneal_path(graph, a, settings);
    for (int c = 1; c < chains && chain.nodes.size() >= 2; ++c) {
        const MotionPath next = anneal_path(graph, chain.nodes.back(), settings);
        if (next.nodes.size() < 2) break;
        chain.nodes.insert(chain.nodes.end(), next.nodes.begin() + 1, next.nodes.end());
        chain.energy += next.energy, chain.direct_energy += next.direct_energy;
        chain.at_bound = chain.at_bound || next.at_bound;
    }
    return chain;
}

int path_chains(int new_frames, int path_length) {
    const long chains = std::lround(double(new_frames) / (double(path_length) * kFramesPerStep));
    return static_cast<int>(std::clamp<long>(chains, 1, kMaxChains));
}

void add_path_stats(const std::vector<MotionPath>& paths, GraphMotionStats& stats) {
    int with_path = 0;
    for (const MotionPath& p : paths) {
        if (p.nodes.size() < 2) {
            ++stats.still_samples;
            continue;
        }
        ++with_path;
        stats.direct_energy += p.direct_energy, stats.path_energy += p.energy;
        stats.path_steps += static_cast<double>(p.nodes.size() - 1);
        stats.anneal_bound_hits += p.at_bound ? 1 : 0;
    }
    if (with_path > 0) stats.direct_energy /= with_path, stats.path_energy /= with_path, stats.path_steps /= with_path;
}

}  // namespace tessera::dynamic
