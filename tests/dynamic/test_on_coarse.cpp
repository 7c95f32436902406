// All-frame synthesis on a coarse motion (synthesize_on_coarse): noodles follow their coarse
// swing and keep their sample spacing, and their details do not bend them into each other;
// paper sheets keep their grid (no flipped quad) and
// their edge lengths; the exemplar's detail is carried over; neighbouring threads keep the
// exemplar's relation between their kinks (the cross part of the neighbourhoods);
// determinism; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "analysis/motion_fixtures.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"

namespace {

using namespace tessera;

Animation example(const std::string& name) {
    return load_animation(std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/" + name + ".json");
}

// Largest |length / reference - 1| over the thread segments of every element and frame,
// the reference being the element's mean segment length in frame 0.
double worst_thread_strain(const Animation& a) {
    double worst = 0.0;
    for (const Element& e : a.structure.elements) {
        double mean = 0.0;
        for (int k = 0; k + 1 < e.sample_count; ++k)
            mean += norm(a.at(0, e.first_sample + k + 1) - a.at(0, e.first_sample + k));
        mean /= e.sample_count - 1;
        for (int f = 0; f < a.frame_count(); ++f)
            for (int k = 0; k + 1 < e.sample_count; ++k) {
                const double l = norm(a.at(f, e.first_sample + k + 1) - a.at(f, e.first_sample + k));
                worst = std::max(worst, std::abs(l / mean - 1.0));
            }
    }
    return worst;
}

double rms_offset(const Animation& a, const Animation& b) {
    double sum = 0.0;
    for (size_t k = 0; k < a.positions.size(); ++k) sum += squared_norm(a.positions[k] - b.positions[k]);
    return std::sqrt(sum / a.positions.size());
}

DynamicOptions options(int threads = 2) {
    DynamicOptions o;
    o.seed = 3;
    o.threads = threads;
    return o;
}

// `count` vertical threads of 16 samples, 1.2 apart, over 40 frames, each with a kink running
// along it in time; thread n's kink is shifted by n x `phase_step` (pi: each thread's kinks
// mirror its neighbours'). With `amplitude` 0 the threads are straight and still (a coarse
// motion).
Animation parallel_threads(int count, double amplitude, double phase_step) {
    Animation a = motion_test::animation_of(
        "noodle", ElementTopology::thread, 0, count, 16, 40,
        [=](int n, int i, int f) {
            const double kink =
                amplitude * std::sin(2 * std::numbers::pi * (i / 5.0 + f * 0.1 / 1.6) + n * phase_step);
            return Vec3{1.0 + 1.2 * n + kink, 4.5 - 0.25 * i, 0};
        },
        Domain::box({0, 0, 0}, {1.2 * count + 1, 5, 0}, 2));
    a.structure.types[0].rigid = false;
    return a;
}

// Mean over pairs of neighbouring threads of the correlation of their x offsets from their
// own mean place, over every sample and frame.
double neighbour_correlation(const Animation& a) {
    const int threads = static_cast<int>(a.structure.elements.size());
    std::vector<std::vector<double>> x(threads);
    for (int n = 0; n < threads; ++n) {
        const Element& e = a.structure.elements[n];
        double mean = 0.0;
        for (int f = 0; f < a.frame_count(); ++f)
            for (int k = 0; k < e.sample_count; ++k) x[n].push_back(a.at(f, e.first_sample + k).x), mean += x[n].back();
        mean /= x[n].size();
        for (double& v : x[n]) v -= mean;
    }
    double sum = 0.0;
    for (int n = 0; n + 1 < threads; ++n) {
        double ab = 0.0, aa = 0.0, bb = 0.0;
        for (size_t k = 0; k < x[n].size(); ++k) ab += x[n][k] * x[n + 1][k], aa += x[n][k] * x[n][k], bb += x[n + 1][k] * x[n + 1][k];
        sum += ab / std::sqrt(aa * bb);
    }
    return sum / (threads - 1);
}

// The grid part of a neighbourhood matches each thread's detail within the thread: patches of
// exemplar threads copied side by side keep their kinks, but not how the kinks of
// neighbouring threads go together. The cross part does: in an exemplar whose neighbouring
// threads kink in mirror image (correlation -1), the output's neighbours come out at -0.61 to
// -0.69 for seeds 1 to 3 (-0.95 with 16 iterations) against -0.34 to 0.16 without it.
TEST(DynamicOnCoarse, NeighbouringThreadsKeepHowTheirKinksGoTogether) {
    const Animation exemplar = parallel_threads(6, 0.08, std::numbers::pi), coarse = parallel_threads(12, 0.0, 0.0);
    ASSERT_LT(neighbour_correlation(exemplar), -0.99);
    DynamicOptions o = options();
    double with_mean = 0.0, grid_mean = 0.0;
    for (std::uint64_t seed : {1, 2, 3}) {
        o.seed = seed;
        o.cross_weight = 1.0;
        const double with_cross = neighbour_correlation(synthesize_on_coarse(exemplar, coarse, o));
        o.cross_weight = 0.0;
        const double grid_only = neighbour_correlation(synthesize_on_coarse(exemplar, coarse, o));
        EXPECT_LT(with_cross, -0.5) << "seed " << seed << ": without the cross part " << grid_only;
        with_mean += with_cross / 3, grid_mean += grid_only / 3;
    }
    EXPECT_LT(with_mean, grid_mean - 0.4) << "with the cross part " << with_mean << ", without " << grid_mean;
}

TEST(DynamicOnCoarse, NoodlesFollowTheirCoarseSwingAndKeepTheirSpacing) {
    const Animation exemplar = example("noodles_2d"), coarse = example("noodles_coarse_2d");
    const AnimatedArrangement out = synthesize_on_coarse(exemplar, coarse, options());
    ASSERT_EQ(out.frame_count(), coarse.frame_count());
    ASSERT_EQ(out.sample_count(), coarse.sample_count());
    EXPECT_LT(worst_thread_strain(out), 0.05);
    // Detail was laid on: the output is off its coarse motion by about the exemplar's kinks
    // (amplitude ~0.07-0.1), yet no sample strays more than a few of them.
    const double rms = rms_offset(out, coarse);
    EXPECT_GT(rms, 0.03);
    EXPECT_LT(rms, 0.3);
    // Every noodle follows its coarse path: its centroid stays near the coarse one.
    for (int f = 0; f < out.frame_count(); f += 7)
        for (const Element& e : out.structure.elements) {
            Vec3 a, b;
            for (int k = 0; k < e.sample_count; ++k)
                a += out.at(f, e.first_sample + k), b += coarse.at(f, e.first_sample + k);
            EXPECT_LT(norm(a - b) / e.sample_count, 0.3) << "frame " << f;
        }
}

// Closest approach of two different elements in frame f.
double closest_between_elements(const Animation& a, int f) {
    double best = 1e300;
    for (int i = 0; i < a.sample_count(); ++i)
        for (int j = i + 1; j < a.sample_count(); ++j)
            if (a.structure.samples[i].element != a.structure.samples[j].element)
                best = std::min(best, norm(a.at(f, i) - a.at(f, j)));
    return best;
}

// The noodles packed 2.5 times closer than the demo's coarse motion (0.19 apart, their kinks
// 0.07-0.1 each way): the details alone would bend neighbours into each other; the contacts
// keep every pair at least about half its coarse distance apart (without them: 0.03).
TEST(DynamicOnCoarse, DetailsDoNotBendNeighbouringNoodlesIntoEachOther) {
    const Animation exemplar = example("noodles_2d");
    Animation coarse = example("noodles_coarse_2d");
    for (Vec3& p : coarse.positions) p.x *= 0.4;
    const AnimatedArrangement out = synthesize_on_coarse(exemplar, coarse, options());
    for (int f = 0; f < out.frame_count(); f += 3) {
        const double apart = closest_between_elements(out, f), coarse_apart = closest_between_elements(coarse, f);
        EXPECT_GT(apart, 0.4 * coarse_apart) << "frame " << f;  // half, less what the last lengths pass moves
    }
    EXPECT_LT(worst_thread_strain(out), 0.05);
}

TEST(DynamicOnCoarse, SheetsKeepTheirGridWithoutFlippedQuads) {
    const Animation exemplar = example("paper_3d"), coarse = example("paper_coarse_3d");
    const AnimatedArrangement out = synthesize_on_coarse(exemplar, coarse, options());
    const int columns = out.structure.types[0].sheet_columns;
    int flipped = 0, quads = 0;
    double worst = 0.0;
    for (int f = 0; f < out.frame_count(); ++f)
        for (const Element& e : out.structure.elements)
            for (int r = 0; r + 1 < e.sample_count / columns; ++r)
                for (int c = 0; c + 1 < columns; ++c) {
                    const int s = e.first_sample + r * columns + c;
                    const auto normal = [&](const Animation& a) {
                        return cross(a.at(f, s + 1) - a.at(f, s), a.at(f, s + columns) - a.at(f, s));
                    };
                    flipped += dot(normal(out), normal(coarse)) <= 0.0;
                    ++quads;
                    const double rest = norm(coarse.at(0, s + 1) - coarse.at(0, s));
                    worst = std::max(worst, std::abs(norm(out.at(f, s + 1) - out.at(f, s)) / rest - 1.0));
                }
    EXPECT_EQ(flipped, 0) << "of " << quads;
    // Flutter makes the sheet a little longer than its flat coarse (the exemplar's stretch).
    EXPECT_LT(worst, 0.05);
    EXPECT_GT(rms_offset(out, coarse), 0.01);
}

// Whether a segment pq crosses the triangle abc (a point of it strictly between p and q).
bool segment_crosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = cross(b - a, c - a);
    const double dp = dot(p - a, n), dq = dot(q - a, n);
    if (dp * dq >= 0.0) return false;
    const Vec3 x = p + (q - p) * (dp / (dp - dq));
    return dot(cross(b - a, x - a), n) >= 0.0 && dot(cross(c - b, x - b), n) >= 0.0 &&
           dot(cross(a - c, x - c), n) >= 0.0;
}

// Frames in which an edge of one sheet of `a` passes through a triangle of another.
int frames_with_sheets_crossing(const Animation& a) {
    const int columns = a.structure.types[0].sheet_columns;
    int crossing = 0;
    for (int f = 0; f < a.frame_count(); ++f) {
        bool any = false;
        for (const Element& e : a.structure.elements)
            for (const Element& o : a.structure.elements) {
                if (&e == &o) continue;
                const int rows = e.sample_count / columns;
                const auto at = [&](const Element& x, int r, int c) { return a.at(f, x.first_sample + r * columns + c); };
                for (int r = 0; r < rows && !any; ++r)
                    for (int c = 0; c < columns && !any; ++c)
                        for (const auto& [dr, dc] : {std::pair{0, 1}, std::pair{1, 0}}) {
                            if (r + dr >= rows || c + dc >= columns) continue;
                            const Vec3 p = at(e, r, c), q = at(e, r + dr, c + dc);
                            for (int tr = 0; tr + 1 < rows && !any; ++tr)
                                for (int tc = 0; tc + 1 < columns && !any; ++tc)
                                    any = segment_crosses(p, q, at(o, tr, tc), at(o, tr, tc + 1), at(o, tr + 1, tc + 1)) ||
                                          segment_crosses(p, q, at(o, tr, tc), at(o, tr + 1, tc + 1), at(o, tr + 1, tc));
                        }
            }
        crossing += any;
    }
    return crossing;
}

// Two flat sheets falling stacked 0.02 apart, less than the exemplar's flutter (waves of 0.08
// and 0.04 across its sheets): their details fold them into each other, and holding their
// samples apart (element_contacts.hpp) did not stop them crossing between the samples (13 of
// 40 frames); kept on their coarse sides (sheet_sides.hpp), no edge of one passes through the
// other in any frame.
TEST(DynamicOnCoarse, StackedSheetsNeverPassThroughEachOther) {
    const Animation exemplar = example("paper_3d");
    const Animation coarse = motion_test::animation_of(
        "paper", ElementTopology::sheet, 6, 2, 36, 40,
        [](int sheet, int k, int f) {
            return Vec3{1.5 + 0.2 * (k % 6) + 0.1 * sheet, 1.5 + 0.2 * (k / 6), 3.0 + 0.02 * sheet - 0.03 * f};
        },
        Domain::box({0, 0, 0}, {4, 4, 4}, 3));
    ASSERT_EQ(frames_with_sheets_crossing(coarse), 0);
    const AnimatedArrangement out = synthesize_on_coarse(exemplar, coarse, options());
    EXPECT_GT(rms_offset(out, coarse), 0.01);  // they do flutter
    EXPECT_EQ(frames_with_sheets_crossing(out), 0);
}

// `count` threads of 16 samples placed by `at(thread, sample, frame)`, 40 frames, in 3D.
Animation threads_3d(int count, const motion_test::Motion& at) {
    return motion_test::animation_of("hair", ElementTopology::thread, 0, count, 16, 40, at,
                                     Domain::box({0, 0, 0}, {6, 6, 6}, 3));
}

// Frames in which a segment of one thread of `a` passes through a segment of another: the
// sign of their separation along the common normal differs from the first frame's.
int frames_with_threads_crossing(const Animation& a) {
    const Element& e = a.structure.elements[0];
    const Element& o = a.structure.elements[1];
    const auto sides = [&](int f) {
        std::vector<int> out;
        for (int i = 0; i + 1 < e.sample_count; ++i)
            for (int j = 0; j + 1 < o.sample_count; ++j) {
                const Vec3 p0 = a.at(f, e.first_sample + i), p1 = a.at(f, e.first_sample + i + 1);
                const Vec3 q0 = a.at(f, o.first_sample + j), q1 = a.at(f, o.first_sample + j + 1);
                const Vec3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
                const double aa = dot(u, u), b = dot(u, v), c = dot(v, v), d = dot(u, w), ee = dot(v, w);
                const double det = aa * c - b * b, s = (b * ee - c * d) / det, t = (aa * ee - b * d) / det;
                if (!(s > 0 && s < 1 && t > 0 && t < 1)) continue;
                out.push_back(dot((p0 + u * s) - (q0 + v * t), Vec3{0, 0, 1}) > 0 ? 1 : -1);
            }
        return out;
    };
    const std::vector<int> first = sides(0);
    int crossing = 0;
    for (int f = 1; f < a.frame_count(); ++f) crossing += sides(f) != first;
    return crossing;
}

// Hair in 3D: two straight threads crossing 0.02 apart, one over the other, dressed with the
// detail of threads coiling 0.1 about their line. Holding their samples apart did not stop the
// coils taking one through the other between their samples; kept on their coarse sides
// (thread_sides.hpp), the upper stays above the lower in every frame.
TEST(DynamicOnCoarse, CrossingThreadsIn3DNeverPassThroughEachOther) {
    const Animation exemplar = threads_3d(4, [](int e, int k, int f) {
        const double phase = 0.8 * k - 0.5 * f + 1.3 * e;
        return Vec3{1.0 + 0.25 * k, 1.0 + e, 3.0} + Vec3{0, 0.1 * std::cos(phase), 0.1 * std::sin(phase)};
    });
    const Animation coarse = threads_3d(2, [](int e, int k, int) {
        // Crossing at (3, 3), halfway between samples of both; the second 0.02 above the first.
        return e == 0 ? Vec3{1.125 + 0.25 * k, 3.0, 3.0} : Vec3{3.0, 1.125 + 0.25 * k, 3.02};
    });
    ASSERT_EQ(frames_with_threads_crossing(coarse), 0);
    const AnimatedArrangement out = synthesize_on_coarse(exemplar, coarse, options());
    EXPECT_GT(rms_offset(out, coarse), 0.03);  // they do coil
    EXPECT_EQ(frames_with_threads_crossing(out), 0);  // 21 of 39 frames without the sides
    EXPECT_TRUE(synthesize_on_coarse(exemplar, coarse, options(1)).positions == out.positions);
    EXPECT_TRUE(synthesize_on_coarse(exemplar, coarse, options(3)).positions == out.positions);
}

TEST(DynamicOnCoarse, SameBitsForEveryThreadCount) {
    const Animation exemplar = example("noodles_2d"), coarse = example("noodles_coarse_2d");
    const AnimatedArrangement one = synthesize_on_coarse(exemplar, coarse, options(1));
    for (int threads : {2, 3}) {
        const AnimatedArrangement other = synthesize_on_coarse(exemplar, coarse, options(threads));
        EXPECT_TRUE(one.positions == other.positions) << threads << " threads";
    }
}

TEST(DynamicOnCoarse, RejectsACoarseMotionTheExemplarCannotDress) {
    const Animation exemplar = example("noodles_2d");
    Animation coarse = example("noodles_coarse_2d");
    coarse.structure.types[0].name = "spaghetti";
    try {
        synthesize_on_coarse(exemplar, coarse, options());
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("type 'spaghetti' is not in the exemplar"), std::string::npos);
    }
    EXPECT_THROW(synthesize_on_coarse(exemplar, example("paper_coarse_3d"), options()), Error);
    // A type the exemplar declares but has no element of: nothing to copy from.
    Animation bare = exemplar;
    bare.structure.types.push_back(bare.structure.types[0]);
    bare.structure.types[0].name = "unused";
    try {
        synthesize_on_coarse(bare, example("noodles_coarse_2d"), options());
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("has no element in the exemplar"), std::string::npos) << e.what();
    }
    DynamicOptions bad = options();
    bad.topology_size = 1;
    EXPECT_THROW(synthesize_on_coarse(exemplar, example("noodles_coarse_2d"), bad), Error);
}

}  // namespace
