// dynamic/cross_neighbours.cpp — the samples of other elements in a detail neighbourhood.
#include "dynamic/cross_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"

namespace tessera::dynamic {

static_assert(CrossNeighbours::kMax == DetailMatches::kCross, "one bound on the cross entries");

CrossNeighbours::CrossNeighbours(const std::vector<Vec3>& coarse, const std::vector<LocalFrame>& frames,
                                 const std::vector<int>& element_of, int frame_count, double radius, int dimension,
                                 int threads) {
    const int samples = static_cast<int>(element_of.size());
    const size_t total = static_cast<size_t>(frame_count) * samples;
    entries_.assign(total * kMax, CrossEntry{});
    count_.assign(total, 0);
    if (!(radius > 0.0) || samples == 0) return;
    core::parallel_for(frame_count, threads, [&](int begin, int end, int) {
        core::SpatialGrid grid;
        std::vector<Vec3> points;
        std::vector<std::pair<double, int>> near;
        for (int f = begin; f < end; ++f) {
            const Vec3* p = coarse.data() + static_cast<size_t>(f) * samples;
            points.assign(p, p + samples);
            grid.build(points, radius, dimension);
            for (int s = 0; s < samples; ++s) {
                near.clear();
                grid.for_each_within(points[s], radius, [&](int o, double d2) {
                    if (element_of[o] != element_of[s]) near.push_back({d2, o});
                });
                std::sort(near.begin(), near.end());  // nearest first, ties by index
                const size_t k = static_cast<size_t>(f) * samples + s;
                const int n = std::min<int>(kMax, static_cast<int>(near.size()));
                for (int e = 0; e < n; ++e)
                    entries_[k * kMax + e] = {near[e].second, frames[k].to_local(points[near[e].second] - points[s])};
                count_[k] = n;
            }
        }
    });
}

double cross_radius(const std::vector<Vec3>& coarse, const std::vector<int>& element_of, int frame_count,
                    int dimension) {
    const int samples = static_cast<int>(element_of.size());
    if (samples == 0 || std::all_of(element_of.begin(), element_of.end(), [&](int e) { return e == element_of[0]; }))
        return 0.0;
    std::vector<double> nearest;
    std::vector<Vec3> points;
    core::SpatialGrid grid;
    for (int f = 0; f < frame_count; ++f) {
        const Vec3* p = coarse.data() + static_cast<size_t>(f) * samples;
        points.assign(p, p + samples);
        Vec3 lo = points[0], hi = points[0];
        for (const Vec3& q : points)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
        const double cell = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-9}) / 8.0;
        grid.build(points, cell, dimension);
        for (int s = 0; s < samples; ++s) {
            double best = std::numeric_limits<double>::infinity();
            for (double r = cell; !std::isfinite(best) && r < 64.0 * cell; r *= 2.0)
                grid.for_each_within(points[s], r, [&](int o, double d2) {
                    if (element_of[o] != element_of[s]) best = std::min(best, d2);
                });
            if (std::isfinite(best)) nearest.push_back(std::sqrt(best));
        }
    }
    if (nearest.empty()) return 0.0;
    std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
    return 1.5 * nearest[nearest.size() / 2];
}

Vec3 relative_detail(const DetailField& field, const std::vector<LocalFrame>& frames, int ka, int kb) {
    return frames[ka].to_local(frames[kb].to_world(field.detail[kb])) - field.detail[ka];
}

namespace {

// When every row's cheapest column is its own (no two rows want the same input entry; any
// number may stay unpaired, each in a dummy column), giving each row its minimum reaches the
// lower bound of any assignment: it is optimal and the Hungarian algorithm is not needed.
// Neighbouring samples lie in different directions, so this is the common case. Writes the
// columns and returns true then.
bool own_minima_pair(const double* cost, int rows, int real, int cols, int* column) {
    int dummy = real;
    for (int r = 0; r < rows; ++r) {
        const double* row = cost + static_cast<size_t>(r) * cols;
        int best = real;  // a dummy (they all cost the same for one row)
        for (int c = 0; c < real; ++c)
            if (row[c] < row[best == real ? real : best]) best = c;
        for (int q = 0; q < r; ++q)
            if (best < real && column[q] == best) return false;
        column[r] = best < real ? best : dummy++;
    }
    return true;
}

}  // namespace

double cross_distance(const CrossTerm& term, const DetailField& out, int f, int s, const DetailField& in, int g,
                      int j, double cap2, CrossScratch& scratch, int* partner) {
    const int ko = f * out.samples + s, ki = g * in.samples + j;
    const int no = term.out->count(ko), ni = term.in->count(ki);
    if (partner) std::fill(partner, partner + no, -1);
    if (no == 0 || ni == 0) return term.weight * cap2 * (no + ni);
    const CrossEntry* eo = term.out->entries(ko);
    const CrossEntry* ei = term.in->entries(ki);
    // Rows: the output entries; columns: the input entries, then one "unpaired" column per
    // row, so that every row has a column however few input entries there are.
    const int cols = ni + no;
    scratch.cost.assign(static_cast<size_t>(no) * cols, 0.0);
    for (int r = 0; r < no; ++r) {
        for (int c = 0; c < ni; ++c) scratch.cost[r * cols + c] = squared_norm(eo[r].place - ei[c].place);
        // Left unpaired when no input entry lies within the place's own distance from the
        // centre (a neighbour twice as far is another neighbour).
        for (int c = ni; c < cols; ++c) scratch.cost[r * cols + c] = squared_norm(eo[r].place);
    }
    scratch.column.resize(no);
    if (!own_minima_pair(scratch.cost.data(), no, ni, cols, scratch.column.data()))
        core::hungarian(scratch.cost.data(), no, cols, scratch.hungarian, scratch.column.data());
    double sum = 0.0;
    int paired = 0;
    for (int r = 0; r < no; ++r) {
        const int c = scratch.column[r];
        if (c >= ni) {
            sum += cap2;
            continue;
        }
        ++paired;
        const Vec3 ro = relative_detail(out, *term.out_frames, ko, f * out.samples + eo[r].sample);
        const Vec3 ri = relative_detail(in, *term.in_frames, ki, g * in.samples + ei[c].sample);
        sum += squared_norm(ro - ri);
        if (partner) partner[r] = ei[c].sample;
    }
    sum += cap2 * (ni - paired);
    return term.weight * sum;
}

}  // namespace tessera::dynamic
