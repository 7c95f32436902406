// The low-pass filter of threads and sheets along their own topology (Dynamic Element
// Textures, section 5, Figure 7: hair, whose coarse motion is the slow sway of each strand
// and whose details are the strand's fine waves). A thread is a grid of one row, a sheet of
// rows x columns; the kernel is a separable Gaussian over rows and columns whose half-widths
// shrink symmetrically near the ends and borders, so that a straight thread or a flat
// (linear) sheet comes out exactly as it went in, up to its last sample.
#include "analysis/low_pass.hpp"
#include "core/parallel.hpp"

namespace tessera::analysis {

namespace {

struct Window {
    int half = 0;
    std::vector<double> g;
};

// The windows of every index 0..n-1 of one axis.
std::vector<Window> axis_windows(int n, int radius) {
    std::vector<Window> w(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        w[i].half = symmetric_half_width(radius, i, n);
        w[i].g = gaussian_half_window(w[i].half, radius);
    }
    return w;
}

// The filtered position of sample (r, c) of an element whose samples at this frame start at
// `first` of `values`.
Vec3 grid_average(const Vec3* first, int columns, const Window& wr, int r, const Window& wc, int c) {
    Vec3 sum;
    double total = 0.0;
    for (int a = -wr.half; a <= wr.half; ++a) {
        const double ga = wr.g[a < 0 ? -a : a];
        for (int b = -wc.half; b <= wc.half; ++b) {
            const double w = ga * wc.g[b < 0 ? -b : b];
            sum += first[(r + a) * columns + (c + b)] * w;
            total += w;
        }
    }
    return sum / total;
}

}  // namespace

void grid_low_pass(const Animation& input, const std::vector<Layout>& layouts,
                   const std::vector<Vec3>& smoothed, int topology_radius, int threads,
                   std::vector<Vec3>& coarse) {
    std::vector<int> grids;
    for (size_t i = 0; i < layouts.size(); ++i)
        if (layouts[i].kind == Kind::grid) grids.push_back(static_cast<int>(i));
    const int frames = input.frame_count(), samples = input.sample_count();
    const int jobs = static_cast<int>(grids.size()) * frames;
    // One job per (element, frame); each writes only that element's samples of that frame.
    core::parallel_for(
        jobs, threads,
        [&](int begin, int end, int) {
            for (int job = begin; job < end; ++job) {
                const int e = grids[job / frames], f = job % frames;
                const Layout& l = layouts[e];
                const std::vector<Window> rows = axis_windows(l.rows, topology_radius);
                const std::vector<Window> columns = axis_windows(l.columns, topology_radius);
                const size_t base =
                    static_cast<size_t>(f) * samples + input.structure.elements[e].first_sample;
                for (int r = 0; r < l.rows; ++r)
                    for (int c = 0; c < l.columns; ++c)
                        coarse[base + r * l.columns + c] =
                            grid_average(&smoothed[base], l.columns, rows[r], r, columns[c], c);
            }
        },
        16);
}

}  // namespace tessera::analysis
