// dynamic/detail_assign.cpp — the assignment step of all-frame detail synthesis
// (detail_field.hpp): Eq. 7 solved Jacobi-style, as the paper's "Parallelization" paragraph
// does, with the N-best blend of Eq. 11-12.
#include "core/parallel.hpp"
#include "dynamic/detail_field.hpp"
#include "dynamic/frame_search.hpp"

namespace tessera::dynamic {

namespace {

// Every neighbourhood covering (s, f) at offset o is centred at (s - o, f - o.dt); each of its
// matches (j, g) predicts the detail at (s, f) as the centre's detail plus the input's
// relative detail at the same offset (Eq. 6); the centre offset predicts the absolute detail.
Vec3 assign_one(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                const std::vector<GridOffset>& offsets, int f, int s) {
    Vec3 sum;
    double weight = 0.0;
    double omega[8];
    for (const GridOffset& o : offsets) {
        const int c = out.grid.step(s, -o.dr, -o.dc), fc = f - o.dt;
        if (!out.valid(fc, c)) continue;
        const int k = fc * out.samples + c;
        const int* m = matches.of(k);
        int count = 0;
        while (count < matches.n && m[count] >= 0) ++count;
        blend_weights(matches.cost_of(k), count, omega);
        for (int q = 0; q < count; ++q) {
            const int j = m[q] % in.samples, g = m[q] / in.samples;
            const int je = in.grid.step(j, o.dr, o.dc), ge = g + o.dt;
            if (!in.valid(ge, je)) continue;
            const bool centre = o.dr == 0 && o.dc == 0 && o.dt == 0;
            const Vec3 prediction = centre ? in.at(g, j) : out.at(fc, c) + (in.at(ge, je) - in.at(g, j));
            const double w = o.kappa * omega[q];
            sum += prediction * w;
            weight += w;
        }
    }
    return weight > 0.0 ? sum / weight : out.at(f, s);
}

}  // namespace

std::vector<Vec3> assign_details(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                                 const std::vector<std::vector<GridOffset>>& offsets, int threads) {
    std::vector<Vec3> next(out.detail.size());
    const int n = out.frames * out.samples;
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int) {
            for (int k = begin; k < end; ++k) {
                const int s = k % out.samples;
                next[k] = assign_one(in, out, matches, offsets[out.type[s]], k / out.samples, s);
            }
        },
        256);
    return next;
}

}  // namespace tessera::dynamic
