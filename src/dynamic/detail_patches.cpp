// dynamic/detail_patches.cpp — patch-copy initialization of all-frame detail synthesis.
#include "dynamic/detail_patches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace tessera::dynamic {

namespace {

struct Source {
    int element = -1, frame = 0;  // exemplar element and the frame the window starts at
};

// The exemplar sample at the same relative place on its element's grid as output sample s.
int mapped_sample(const DetailField& in, int in_element, const DetailField& out, int s) {
    const auto place = [](int index, int from, int to) {
        return from <= 1 ? 0 : static_cast<int>(std::lround(double(index) * (to - 1) / (from - 1)));
    };
    const int e = out.grid.element(s);
    return in.grid.at(in_element, place(out.grid.row(s), out.grid.rows(e), in.grid.rows(in_element)),
                      place(out.grid.col(s), out.grid.cols(e), in.grid.cols(in_element)));
}

std::vector<int> elements_of_type(const DetailField& in, int type) {
    std::vector<int> list;
    for (int e = 0; e < in.grid.element_count(); ++e)
        if (in.type[in.grid.at(e, 0, 0)] == type) list.push_back(e);
    return list;
}

// The exemplar (element, frame g >= 1) whose frame g - 1 is nearest the output's frame
// f - 1 over the element's samples, so that the window starting at g continues it.
Source best_continuation(const DetailField& in, const DetailField& out, const std::vector<int>& candidates,
                         const std::vector<int>& samples, int f, int window) {
    Source best{candidates[0], 0};  // the exemplar too short to continue: start over
    double best_cost = std::numeric_limits<double>::infinity();
    for (int je : candidates)
        for (int g = 1; g + window <= in.frames; ++g) {
            double cost = 0.0;
            for (int s : samples) cost += squared_norm(in.at(g - 1, mapped_sample(in, je, out, s)) - out.at(f - 1, s));
            if (cost < best_cost) best_cost = cost, best = {je, g};
        }
    return best;
}

void copy_window(const DetailField& in, DetailField& out, DetailMatches& matches, const std::vector<int>& samples,
                 const Source& source, int f, int length) {
    for (int k = 0; k < length; ++k)
        for (int s : samples) {
            const int j = mapped_sample(in, source.element, out, s), g = source.frame + k;
            out.at(f + k, s) = in.at(g, j);
            matches.of((f + k) * out.samples + s)[0] = g * in.samples + j;
        }
}

void copy_element(const DetailField& in, DetailField& out, DetailMatches& matches, int e, int window,
                  std::uint64_t seed) {
    std::vector<int> samples;
    for (int r = 0; r < out.grid.rows(e); ++r)
        for (int c = 0; c < out.grid.cols(e); ++c) samples.push_back(out.grid.at(e, r, c));
    const std::vector<int> candidates = elements_of_type(in, out.type[samples[0]]);
    const int length = std::min(window, in.frames);
    const core::KeyedRng rng(seed, core::Purpose::dynamic_patch, static_cast<std::uint64_t>(e));
    Source source{candidates[rng.below(0, candidates.size())],
                  static_cast<int>(rng.below(1, static_cast<std::uint64_t>(in.frames - length + 1)))};
    for (int f = 0; f < out.frames; f += length) {
        if (f > 0) {
            source.frame += length;
            if (source.frame + length > in.frames) source = best_continuation(in, out, candidates, samples, f, length);
        }
        copy_window(in, out, matches, samples, source, f, std::min(length, out.frames - f));
    }
}

}  // namespace

void copy_patches(const DetailField& in, DetailField& out, DetailMatches& matches, int window, std::uint64_t seed,
                  int threads) {
    core::parallel_for(out.grid.element_count(), threads, [&](int begin, int end, int) {
        for (int e = begin; e < end; ++e) copy_element(in, out, matches, e, window, seed);
    });
}

}  // namespace tessera::dynamic
