// Tests of the 2D image mask domain: a PNG written here, measure, inside, the
// conservative distance_to_boundary, closest_inside, and the empty / unreadable errors.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/error.hpp"

using namespace tessera;

namespace {

// A 64 x 64 PNG, white inside a disk of radius 24 pixels centred in the image.
std::string write_disk_png(const std::string& name, bool empty = false) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    std::vector<unsigned char> pixels(64 * 64, 0);
    for (int r = 0; r < 64; ++r)
        for (int i = 0; i < 64; ++i)
            if (!empty && std::hypot(i + 0.5 - 32, r + 0.5 - 32) < 24) pixels[r * 64 + i] = 255;
    stbi_write_png(path.c_str(), 64, 64, 1, pixels.data(), 64);
    return path;
}

}  // namespace

TEST(DomainMask, DiskFromPng) {
    const std::string path = write_disk_png("tessera_mask_disk.png");
    // Mapped onto [0, 6.4]^2: a pixel is 0.1, the disk has radius 2.4 around (3.2, 3.2).
    const Domain d = Domain::mask(path, {0, 0, 0}, {6.4, 6.4, 0});
    EXPECT_EQ(d.kind(), Domain::Kind::mask);
    const double area = M_PI * 2.4 * 2.4;
    EXPECT_NEAR(d.measure(), area, 0.02 * area);
    EXPECT_TRUE(d.inside({3.2, 3.2, 0}));
    EXPECT_FALSE(d.inside({0.3, 0.3, 0}));
    EXPECT_FALSE(d.inside({7, 3, 0}));
    EXPECT_DOUBLE_EQ(d.occupancy({3.2, 3.2, 0}), 1.0);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 6.4);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 p{u(rng), u(rng), 0};
        const double truth = 2.4 - std::hypot(p.x - 3.2, p.y - 3.2);
        if (truth > 0.15) { EXPECT_TRUE(d.inside(p)); }
        if (truth < -0.15) { EXPECT_FALSE(d.inside(p)); }
        if (d.inside(p)) { EXPECT_LE(d.distance_to_boundary(p), std::max(0.0, truth) + 0.08); }
        if (!d.inside(p)) {
            const Vec3 q = d.closest_inside(p);
            EXPECT_TRUE(d.inside(q));
            EXPECT_NEAR(std::hypot(q.x - 3.2, q.y - 3.2), 2.4, 0.15);
        }
    }
    std::filesystem::remove(path);
}

TEST(DomainMask, DistanceToBoundaryIsAConservativeBound) {
    // Checked against the mask's own boundary: no point of the disk of that radius is outside.
    const std::string path = write_disk_png("tessera_mask_disk2.png");
    const Domain d = Domain::mask(path, {0, 0, 0}, {6.4, 6.4, 0});
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 6.4), angle(0.0, 2 * M_PI);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p{u(rng), u(rng), 0};
        if (!d.inside(p)) continue;
        const double r = d.distance_to_boundary(p);
        for (int k = 0; k < 32; ++k) {
            const double a = angle(rng), t = r * 0.999;
            EXPECT_TRUE(d.inside(p + Vec3(t * std::cos(a), t * std::sin(a), 0)));
        }
    }
    std::filesystem::remove(path);
}

TEST(DomainMask, EmptyMaskIsADomainErrorNamingTheFile) {
    const std::string path = write_disk_png("tessera_mask_empty.png", true);
    try {
        Domain::mask(path, {0, 0, 0}, {1, 1, 0});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::domain);
        EXPECT_NE(std::string(e.what()).find("tessera_mask_empty.png"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(DomainMask, UnreadableFileIsAnIoError) {
    try {
        Domain::mask("/nonexistent/mask.png", {0, 0, 0}, {1, 1, 0});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::io);
        EXPECT_NE(std::string(e.what()).find("/nonexistent/mask.png"), std::string::npos);
    }
}

TEST(DomainMask, TranslatedOverlapOfAFullMaskIsTheBoxFormula) {
    GrayImage img{4, 2, std::vector<float>(8, 1.0f)};
    const Domain d = Domain::mask(img, {0, 0, 0}, {4, 2, 0});
    EXPECT_DOUBLE_EQ(d.measure(), 8.0);
    EXPECT_NEAR(d.translated_overlap({1, 0.5, 0}), 3 * 1.5, 0.05);
}
