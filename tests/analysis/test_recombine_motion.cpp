// recombine_motion (Dynamic Element Textures, section 5): the coarse motion of one animation
// with the details of another. Frames and elements cycle through the detail's, threads and
// sheets of other sample counts are resampled along their index, and a detail that lacks a
// kind of element the coarse animation has is an error.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/motion_fixtures.hpp"
#include "tessera/error.hpp"
#include "tessera/motion_analysis.hpp"

namespace motion_test {
namespace {

using tessera::ElementTopology;

const tessera::Domain box = tessera::Domain::box({-2, -4, 0}, {30, 30, 0}, 2);

// An arbitrary detail value of (element, sample, frame): not linear, so that resampling
// between the detail's samples would show.
Vec3 wave(int e, int k, int f) {
    return {0.01 * std::sin(1.3 * k + e), 0.02 * std::cos(0.9 * k + 2.0 * f + e), 0};
}

Animation hair(int count, int samples, int frames, const Motion& motion) {
    return animation_of("hair", ElementTopology::thread, 0, count, samples, frames, motion, box);
}

TEST(RecombineMotion, FramesAndElementsCycleThroughTheDetails) {
    const Animation coarse = hair(5, 6, 7, [](int e, int k, int f) {
        return Vec3{0.5 * k + 0.1 * f, 3.0 * e, 0};
    });
    const Animation detail = hair(2, 6, 3, wave);
    const Animation out = tessera::recombine_motion(coarse, detail);
    ASSERT_EQ(out.times, coarse.times);
    double worst = 0.0;
    for (int f = 0; f < 7; ++f)
        for (int e = 0; e < 5; ++e)
            for (int k = 0; k < 6; ++k) {
                const Vec3 expected = coarse.at(f, e * 6 + k) + wave(e % 2, k, f % 3);
                worst = std::max(worst, tessera::norm(out.at(f, e * 6 + k) - expected));
            }
    EXPECT_LT(worst, 1e-12);
}

TEST(RecombineMotion, ThreadsOfAnotherSampleCountAreResampledAlongTheirIndex) {
    // 11 coarse samples on 21 detail samples: coarse sample i lies on detail sample 2i; 21 on
    // 11: even samples on a detail sample, odd ones halfway between two.
    const Motion line = [](int e, int k, int f) { return Vec3{0.25 * k, 2.0 * e + 0.1 * f, 0}; };
    const Animation out = tessera::recombine_motion(hair(1, 11, 2, line), hair(1, 21, 2, wave));
    double worst = 0.0;
    for (int f = 0; f < 2; ++f)
        for (int i = 0; i < 11; ++i)
            worst = std::max(worst, tessera::norm(out.at(f, i) - line(0, i, f) - wave(0, 2 * i, f)));
    EXPECT_LT(worst, 1e-12);
    const Animation fine = tessera::recombine_motion(hair(1, 21, 2, line), hair(1, 11, 2, wave));
    worst = 0.0;
    for (int f = 0; f < 2; ++f)
        for (int i = 0; i < 21; ++i) {
            const Vec3 d = i % 2 ? (wave(0, i / 2, f) + wave(0, i / 2 + 1, f)) * 0.5 : wave(0, i / 2, f);
            worst = std::max(worst, tessera::norm(fine.at(f, i) - line(0, i, f) - d));
        }
    EXPECT_LT(worst, 1e-12);
}

TEST(RecombineMotion, SheetsAreResampledAlongRowsAndColumns) {
    // A 3 x 4 coarse sheet on a 5 x 7 detail sheet: (r, c) lies on detail (2r, 2c).
    const Motion flat = [](int, int k, int) { return Vec3{double(k % 4), double(k / 4), 0}; };
    const Animation coarse = animation_of("cloth", ElementTopology::sheet, 4, 1, 12, 2, flat, box);
    const Animation detail = animation_of("cloth", ElementTopology::sheet, 7, 1, 35, 2, wave, box);
    const Animation out = tessera::recombine_motion(coarse, detail);
    double worst = 0.0;
    for (int f = 0; f < 2; ++f)
        for (int k = 0; k < 12; ++k) {
            const int r = k / 4, c = k % 4;
            worst =
                std::max(worst, tessera::norm(out.at(f, k) - flat(0, k, f) - wave(0, 2 * r * 7 + 2 * c, f)));
        }
    EXPECT_LT(worst, 1e-12);
}

TEST(RecombineMotion, ElementsTakeTheDetailsOfTheirOwnKind) {
    // Coarse: particles then threads; detail: threads then particles. Each element takes the
    // details of the element of its kind with the same rank.
    const Animation dots = animation_of(
        "dot", ElementTopology::none, 0, 2, 1, 2,
        [](int e, int, int) {
            return Vec3{20.0 + e, 20.0, 0};
        },
        box);
    const Animation strands = hair(2, 4, 2, [](int e, int k, int) { return Vec3{double(k), 2.0 * e, 0}; });
    const Animation coarse = merged(dots, strands);
    const Animation detail =
        merged(hair(2, 4, 2, wave), animation_of(
                                        "dot", ElementTopology::none, 0, 2, 1, 2,
                                        [](int e, int, int f) { return wave(e + 7, 0, f); }, box));
    const Animation out = tessera::recombine_motion(coarse, detail);
    for (int f = 0; f < 2; ++f) {
        for (int e = 0; e < 2; ++e)
            EXPECT_LT(tessera::norm(out.at(f, e) - coarse.at(f, e) - wave(e + 7, 0, f)), 1e-12);
        for (int s = 2; s < 10; ++s)
            EXPECT_LT(tessera::norm(out.at(f, s) - coarse.at(f, s) - wave((s - 2) / 4, (s - 2) % 4, f)),
                      1e-12);
    }
}

std::string recombine_error(const Animation& coarse, const Animation& detail) {
    try {
        tessera::recombine_motion(coarse, detail);
    } catch (const tessera::Error& e) {
        EXPECT_EQ(e.kind(), tessera::ErrorKind::input);
        return e.what();
    }
    return "no error";
}

TEST(RecombineMotion, ADetailWithoutTheCoarseKindsOrOfAnotherDimensionIsAnError) {
    const Animation strands = hair(2, 4, 2, wave);
    const Animation dots = animation_of("dot", ElementTopology::none, 0, 3, 1, 2, wave, box);
    EXPECT_EQ(recombine_error(strands, dots),
              "the detail animation has no thread elements for the coarse animation's thread elements (type "
              "'hair')");
    EXPECT_EQ(recombine_error(dots, strands),
              "the detail animation has no particle elements for the coarse animation's particle elements "
              "(type 'dot')");
    const Animation deep = animation_of("dot", ElementTopology::none, 0, 3, 1, 2, wave,
                                        tessera::Domain::box({-2, -4, -1}, {30, 30, 1}, 3));
    EXPECT_EQ(recombine_error(dots, deep), "the coarse animation is 2D and the detail animation 3D");
}

}  // namespace
}  // namespace motion_test
