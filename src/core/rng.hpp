// Counter-based random numbers (DESIGN.md, "API conventions"): every draw is a
// hash of (seed, purpose, a, b, counter), never a shared sequential stream, so
// results do not depend on thread count or scheduling, and a piece of work
// (an element, a tile) can be redone alone and draw the same numbers.
#pragma once

#include <cmath>
#include <cstdint>

namespace tessera::core {

// SplitMix64 finaliser: a bijective 64-bit mixer with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// What a draw is for; part of the key so that purposes never share numbers.
enum class Purpose : std::uint64_t {
    patch_choice = 1,
    patch_offset = 2,
    tie_break = 3,
    jitter = 4,
    pcf_dart = 5,   // PCF synthesis: dart-throwing positions
    pcf_grid = 6,   // PCF synthesis: grid-search jitter
    pcf_radii = 7,  // PCF synthesis: radii drawn to make up a shortfall
    grow_seed = 8,      // growth: where in the exemplar the seed patch is taken
    grow_playout = 9,   // growth: the tree search's random play-outs
    world_seed = 10,    // worlds: where a first-phase tile's seed patches go
    brush_field = 11,   // brushing: the tilt that breaks a symmetric element field's saddle
    dynamic_candidate = 12,  // dynamic: random input samples tried by the search
    dynamic_similarity = 13, // dynamic: input samples scanned for the k-coherence sets
    dynamic_detail = 14,     // dynamic on a coarse motion: random candidates of the detail search
    dynamic_patch = 15,      // dynamic on a coarse motion: the first patch copied onto each element
    dynamic_graph = 16,      // graph synthesis: its node pool and the annealing of its motion paths
    dequantize = 17,         // rounded exemplars: the draw within each coordinate's rounding cell
    grow_squeeze = 18,       // growth: the distance a minority type's inserted element pushes its own to
    test = 99
};

// The key of the cell holding (x, y, z) in a lattice of step `cell` anchored at the world
// origin: draws keyed by it are the same at the same place however large the output is and
// wherever its elements stand in memory.
inline std::uint64_t lattice_key(double x, double y, double z, double cell) {
    auto at = [cell](double v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell))); };
    return mix64(mix64(mix64(at(x)) ^ at(y)) ^ at(z));
}

// A keyed stream: draw(i) is a pure function of (seed, purpose, a, b, i).
class KeyedRng {
public:
    constexpr KeyedRng(std::uint64_t seed, Purpose purpose, std::uint64_t a = 0, std::uint64_t b = 0)
        : key_(mix64(mix64(mix64(seed ^ 0x5851f42d4c957f2dULL) ^ static_cast<std::uint64_t>(purpose)) ^ a) ^
               mix64(b + 0x632be59bd9b4e019ULL)) {}

    constexpr std::uint64_t bits(std::uint64_t counter) const { return mix64(key_ ^ mix64(counter)); }
    // Uniform in [0, 1) with 53 random bits.
    constexpr double uniform(std::uint64_t counter) const {
        return static_cast<double>(bits(counter) >> 11) * 0x1.0p-53;
    }
    // Uniform integer in [0, n), n > 0 (from 53 bits; bias negligible for n << 2^53).
    std::uint64_t below(std::uint64_t counter, std::uint64_t n) const {
        const auto v = static_cast<std::uint64_t>(uniform(counter) * static_cast<double>(n));
        return v < n ? v : n - 1;
    }

private:
    std::uint64_t key_;
};

}  // namespace tessera::core
