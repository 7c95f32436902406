// dynamic/graph_solve.cpp — Jacobi sweeps of Eq. 7 over the still's neighbour pairs.
#include "dynamic/graph_solve.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace tessera::dynamic {

FrameSolver::FrameSolver(const std::vector<PathTracks>& tracks) {
    const int n = static_cast<int>(tracks.size());
    first_.assign(n + 1, 0);
    for (int s = 0; s < n; ++s) first_[s + 1] = first_[s] + tracks[s].tracks();
    neighbour_.resize(first_[n]);
    owner_.resize(first_[n]);
    held_first_.assign(n + 1, 0);
    for (int s = 0; s < n; ++s)
        for (int t = 0; t < tracks[s].tracks(); ++t) {
            neighbour_[first_[s] + t] = tracks[s].neighbour[t];
            owner_[first_[s] + t] = s;
            ++held_first_[tracks[s].neighbour[t] + 1];
        }
    for (int s = 0; s < n; ++s) held_first_[s + 1] += held_first_[s];
    held_track_.resize(first_[n]);
    std::vector<int> fill(held_first_.begin(), held_first_.end() - 1);
    for (int t = 0; t < first_[n]; ++t) held_track_[fill[neighbour_[t]]++] = t;  // in track order
}

int FrameSolver::solve(const std::vector<Vec3>& predicted, std::vector<Vec3>& positions, const Domain& domain,
                       int sweeps, double tolerance, int threads) const {
    const int n = static_cast<int>(positions.size());
    std::vector<Vec3> next(n);
    std::vector<double> moved(n);
    for (int sweep = 1; sweep <= sweeps; ++sweep) {
        core::parallel_for(
            n, threads,
            [&](int begin, int end, int) {
                for (int s = begin; s < end; ++s) {
                    Vec3 sum;
                    int count = 0;
                    for (int t = first_[s]; t < first_[s + 1]; ++t, ++count) sum += positions[neighbour_[t]] - predicted[t];
                    for (int h = held_first_[s]; h < held_first_[s + 1]; ++h, ++count) {
                        const int t = held_track_[h];
                        sum += positions[owner_[t]] + predicted[t];
                    }
                    // Damped by half: plain Jacobi swings a bipartite cluster (two samples that
                    // see only each other) back and forth without end.
                    Vec3 p = count > 0 ? 0.5 * (positions[s] + sum / count) : positions[s];
                    if (!domain.inside(p)) p = domain.closest_inside(p);
                    next[s] = p;
                    moved[s] = squared_norm(p - positions[s]);
                }
            },
            64);
        positions.swap(next);
        if (*std::max_element(moved.begin(), moved.end()) <= tolerance * tolerance) return sweep;
    }
    return -1;
}

}  // namespace tessera::dynamic
