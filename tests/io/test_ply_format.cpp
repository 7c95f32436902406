// Tests for the ASCII PLY writer (src/io/ply_format.cpp): header layout, one vertex
// per sample carrying the element's pose, class names in comments.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tessera/io.hpp"

using namespace tessera;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST(IoPly, HeaderAndOneVertexPerSample) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 1}, 3);
    ex.attribute_names = {"hue", "x"};  // "x" clashes with a coordinate and gets a suffix
    const int stick = ex.type_index("stick");
    const int rock = ex.type_index("big rock");
    const int e = ex.add_element(stick, {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}});
    ex.elements[e].orientation = {0, 0, 1, 0};
    ex.elements[e].scale = 2.5;
    ex.elements[e].attributes = {0.25, 7};
    const int r = ex.add_element(rock, {{0.9, 0.8, 0.7}}, 0.1);
    ex.elements[r].attributes = {1, 2};

    const auto lines = lines_of(to_ply(ex));
    const std::vector<std::string> header = {"ply",
                                             "format ascii 1.0",
                                             "comment tessera dimension 3",
                                             "comment class 0 stick",
                                             "comment class 1 big rock",
                                             "element vertex 3",
                                             "property double x",
                                             "property double y",
                                             "property double z",
                                             "property int element",
                                             "property int sample",
                                             "property int class",
                                             "property double qw",
                                             "property double qx",
                                             "property double qy",
                                             "property double qz",
                                             "property double pscale",
                                             "property double hue",
                                             "property double x_2",
                                             "end_header"};
    ASSERT_EQ(lines.size(), header.size() + 3);
    for (size_t i = 0; i < header.size(); ++i) EXPECT_EQ(lines[i], header[i]);
    EXPECT_EQ(lines[header.size() + 0], "0.1 0.2 0.3 0 0 0 0 0 1 0 2.5 0.25 7");
    EXPECT_EQ(lines[header.size() + 1], "0.4 0.5 0.6 0 1 0 0 0 1 0 2.5 0.25 7");
    EXPECT_EQ(lines[header.size() + 2], "0.9 0.8 0.7 1 0 1 1 0 0 0 1 1 2");
}

TEST(IoPly, TwoDimensionalDataHaveZeroZ) {
    Exemplar ex;
    ex.add_element(ex.type_index("dot"), {{0.5, 0.25, 0}});
    const auto lines = lines_of(to_ply(ex));
    EXPECT_EQ(lines[2], "comment tessera dimension 2");
    EXPECT_EQ(lines.back(), "0.5 0.25 0 0 0 0 1 0 0 0 1");
}
