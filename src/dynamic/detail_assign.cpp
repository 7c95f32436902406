// dynamic/detail_assign.cpp — the assignment step of all-frame detail synthesis
// (detail_field.hpp): Eq. 7 solved Jacobi-style, as the paper's "Parallelization" paragraph
// does, with the N-best blend of Eq. 11-12.
#include "core/parallel.hpp"
#include "dynamic/cross_neighbours.hpp"
#include "dynamic/detail_field.hpp"
#include "dynamic/frame_search.hpp"

namespace tessera::dynamic {

namespace {

// Every neighbourhood covering (s, f) at offset o is centred at (s - o, f - o.dt); each of its
// matches (j, g) predicts the detail at (s, f) as the centre's detail plus the input's
// relative detail at the same offset (Eq. 6); the centre offset predicts the absolute detail.
// The cross part (cross_neighbours.hpp): every sample c that holds (s, f) among its cross
// entries predicts s's detail from each of its matches (j, g) whose pairing gave that entry
// an input partner j': c's own detail plus the input's detail of j' relative to j, turned
// from c's local frame into s's (the world vector of s's detail).
void add_cross_predictions(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                           const CrossTerm& cross, int f, int s, Vec3& sum, double& weight) {
    const int k = f * out.samples + s;
    const CrossEntry* mine = cross.out->entries(k);
    double omega[8];
    for (int e = 0; e < cross.out->count(k); ++e) {
        const int c = mine[e].sample, kc = f * out.samples + c;
        const CrossEntry* theirs = cross.out->entries(kc);
        int slot = -1;  // where s sits among c's entries (the nearest kMax: it may not)
        for (int t = 0; t < cross.out->count(kc) && slot < 0; ++t)
            if (theirs[t].sample == s) slot = t;
        if (slot < 0) continue;
        const int* m = matches.of(kc);
        int count = 0;
        while (count < matches.n && m[count] >= 0) ++count;
        blend_weights(matches.cost_of(kc), count, omega);
        for (int q = 0; q < count; ++q) {
            const int partner = matches.partners(kc, q)[slot];
            if (partner < 0) continue;
            const int g = m[q] / in.samples, j = m[q] % in.samples;
            const Vec3 relative = relative_detail(in, *cross.in_frames, g * in.samples + j, g * in.samples + partner);
            const Vec3 world = (*cross.out_frames)[kc].to_world(out.at(f, c) + relative);
            const double w = cross.weight * omega[q];
            sum += (*cross.out_frames)[k].to_local(world) * w;
            weight += w;
        }
    }
}

Vec3 assign_one(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                const std::vector<GridOffset>& offsets, int f, int s, const CrossTerm* cross) {
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
    if (cross && cross->active()) add_cross_predictions(in, out, matches, *cross, f, s, sum, weight);
    return weight > 0.0 ? sum / weight : out.at(f, s);
}

}  // namespace

std::vector<Vec3> assign_details(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                                 const std::vector<std::vector<GridOffset>>& offsets, int threads,
                                 const CrossTerm* cross) {
    std::vector<Vec3> next(out.detail.size());
    const int n = out.frames * out.samples;
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int) {
            for (int k = begin; k < end; ++k) {
                const int s = k % out.samples;
                next[k] = assign_one(in, out, matches, offsets[out.type[s]], k / out.samples, s, cross);
            }
        },
        256);
    return next;
}

}  // namespace tessera::dynamic
