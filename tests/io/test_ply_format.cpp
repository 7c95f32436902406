// Tests for the ASCII PLY writer (src/io/ply_format.cpp): one vertex per element with
// the names Houdini's instancing uses (orient as x, y, z, w; pscale; id), class names in
// comments, free attributes after the fixed properties, and the id type that holds every id.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// A stick of two samples (rotated half a turn about y, scaled), a rock with a radius,
// and a pebble with a radius whose type has a mesh.
Exemplar three_elements() {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 1}, 3);
    ex.attribute_names = {"hue", "x"};  // "x" clashes with a coordinate and gets a suffix
    const int stick = ex.type_index("stick");
    const int rock = ex.type_index("big rock");
    const int pebble = ex.type_index("pebble");
    ex.types[pebble].mesh = "pebble.obj";
    const int e = ex.add_element(stick, {{0.1, 0.2, 0.3}, {0.5, 0.6, 0.7}});
    ex.elements[e].orientation = {0, 0, 1, 0};
    ex.elements[e].scale = 2.5;
    ex.elements[e].attributes = {0.25, 7};
    ex.elements[e].id = 40;
    const int r = ex.add_element(rock, {{0.9, 0.8, 0.7}}, 0.1);
    ex.elements[r].attributes = {1, 2};
    ex.elements[r].scale = 3;
    ex.elements[r].id = 41;
    const int p = ex.add_element(pebble, {{0.5, 0.5, 0.5}}, 0.3);
    ex.elements[p].attributes = {0, 0};
    ex.elements[p].id = 42;
    return ex;
}

}  // namespace

TEST(IoPly, HeaderAndOneVertexPerElement) {
    const auto lines = lines_of(to_ply(three_elements()));
    const std::vector<std::string> header = {"ply",
                                             "format ascii 1.0",
                                             "comment tessera dimension 3",
                                             "comment class 0 stick",
                                             "comment class 1 big rock",
                                             "comment class 2 pebble",
                                             "element vertex 3",
                                             "property double x",
                                             "property double y",
                                             "property double z",
                                             "property double orient_x",
                                             "property double orient_y",
                                             "property double orient_z",
                                             "property double orient_w",
                                             "property double pscale",
                                             "property int class",
                                             "property uint id",
                                             "property double radius",
                                             "property double hue",
                                             "property double x_2",
                                             "end_header"};
    ASSERT_EQ(lines.size(), header.size() + 3);
    for (size_t i = 0; i < header.size(); ++i) EXPECT_EQ(lines[i], header[i]);
    // The stick at its samples' centroid, orient in Houdini's order (x, y, z, w), pscale = scale.
    EXPECT_EQ(lines[header.size() + 0], "0.3 0.4 0.5 0 1 0 0 2.5 0 40 0 0.25 7");
    // No mesh and a radius: pscale = the radius (a unit sphere copied onto it is the element).
    EXPECT_EQ(lines[header.size() + 1], "0.9 0.8 0.7 0 0 0 1 0.1 1 41 0.1 1 2");
    // A mesh: pscale = the scale, whatever the radius.
    EXPECT_EQ(lines[header.size() + 2], "0.5 0.5 0.5 0 0 0 1 1 2 42 0.3 0 0");
}

TEST(IoPly, TwoDimensionalDataHaveZeroZ) {
    Exemplar ex;
    const int e = ex.add_element(ex.type_index("dot"), {{0.5, 0.25, 0}});
    ex.elements[e].orientation = {0.6, 0, 0, 0.8};  // about z
    const auto lines = lines_of(to_ply(ex));
    EXPECT_EQ(lines[2], "comment tessera dimension 2");
    EXPECT_EQ(lines.back(), "0.5 0.25 0 0 0 0.8 0.6 1 0 0 0");
}

class IoPlyFile : public tessera::test::TempDirTest {};

TEST_F(IoPlyFile, IdsBeyond32BitsAreDoublesAndBeyond53BitsAnError) {
    Exemplar ex;
    const int e = ex.add_element(ex.type_index("dot"), {{0.5, 0.25, 0}});
    ex.elements[e].id = std::uint64_t(1) << 40;
    save(ex, path("big.ply"));
    const std::string text = read("big.ply");
    EXPECT_NE(text.find("property double id\n"), std::string::npos);
    EXPECT_NE(text.find(" 0 1099511627776 0\n"), std::string::npos) << text;

    ex.elements[e].id = (std::uint64_t(1) << 53) + 1;
    try {
        save(ex, path("huge.ply"));
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_EQ(error.kind(), ErrorKind::input);
        const std::string what = error.what();
        EXPECT_NE(what.find("huge.ply"), std::string::npos) << what;
        EXPECT_NE(what.find("9007199254740993"), std::string::npos) << what;
    }
    EXPECT_FALSE(std::filesystem::exists(path("huge.ply")));
}
