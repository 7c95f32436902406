// The shared text forms of options (tessera/option_text.hpp): what `--domain`, `--gravity`,
// `--boundary`, `--search` and `--matching` accept, and that errors name the parameter the
// caller passes (the CLI's flag or the Python keyword).
#include <gtest/gtest.h>

#include "tessera/error.hpp"
#include "tessera/option_text.hpp"

namespace {

using tessera::Error;
using tessera::ErrorKind;

tessera::Exemplar square_exemplar(int dimension) {
    tessera::Exemplar e;
    e.dimension = dimension;
    e.domain = tessera::Domain::box({1, 2, 0}, {11, 12, dimension == 3 ? 10.0 : 0.0}, dimension);
    const int t = e.type_index("dot");
    e.add_element(t, {{5, 5, 0}});
    e.add_element(t, {{6, 6, 0}});
    return e;
}

template <class F>
void expect_error(F&& f, ErrorKind kind, const std::string& needle) {
    try {
        f();
        ADD_FAILURE() << "expected an error containing '" << needle << "'";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

TEST(OptionText, BoxSizeStartsAtTheExemplarsLowerCorner) {
    const auto d = tessera::parse_output_domain("box:30,20", square_exemplar(2), 2.0, "domain");
    EXPECT_DOUBLE_EQ(d.bounds().lo.x, 1.0);
    EXPECT_DOUBLE_EQ(d.bounds().hi.x, 31.0);
    EXPECT_DOUBLE_EQ(d.bounds().hi.y, 22.0);
}

TEST(OptionText, CornersAndPolygonsAreTakenAsGiven) {
    const auto box = tessera::parse_output_domain("box:-5,-5,5,5", square_exemplar(2));
    EXPECT_DOUBLE_EQ(box.measure(), 100.0);
    const auto tri = tessera::parse_output_domain("polygon:0,0,10,0,0,10", square_exemplar(2));
    EXPECT_EQ(tri.kind(), tessera::Domain::Kind::polygon);
    EXPECT_NEAR(tri.measure(), 50.0, 1e-9);
}

TEST(OptionText, ErrorsNameTheParameterTheCallerUses) {
    const auto e2 = square_exemplar(2);
    expect_error([&] { tessera::parse_output_domain("circle:3", e2, 2.0, "domain"); }, ErrorKind::option,
                 "domain: expected box:");
    expect_error([&] { tessera::parse_output_domain("box:3,x", e2, 2.0, "--domain"); }, ErrorKind::option,
                 "--domain: 'x' is not a number");
    expect_error([&] { tessera::parse_output_domain("box:3,-1", e2); }, ErrorKind::option, "must be a number > 0");
    expect_error([&] { tessera::parse_output_domain("box:3,3,3", e2, 2.0, "domain"); }, ErrorKind::domain,
                 "is 3D but the exemplar is 2D");
    expect_error([&] { tessera::parse_output_domain("mesh:bowl.obj", e2); }, ErrorKind::domain, "is 3D");
    expect_error([&] { tessera::parse_output_domain("box:3,3", e2, 0.0, "domain"); }, ErrorKind::option, "scale");
    expect_error([&] { tessera::check_domain_spec("polygon:", "domain"); }, ErrorKind::option, "nothing after");
}

TEST(OptionText, AxisDirectionsAndBoundarySides) {
    EXPECT_EQ(tessera::parse_axis_direction("-z", "gravity"), (tessera::Vec3{0, 0, -1}));
    EXPECT_EQ(tessera::parse_axis_direction("y", "gravity"), (tessera::Vec3{0, 1, 0}));
    expect_error([] { tessera::parse_axis_direction("down", "gravity"); }, ErrorKind::option, "gravity: expected");
    const auto sides = tessera::parse_boundary_sides("-x,+y", "boundary");
    ASSERT_EQ(sides.size(), 2u);
    EXPECT_EQ(sides[0].axis, 0);
    EXPECT_EQ(sides[0].sign, -1);
    EXPECT_EQ(sides[1].axis, 1);
    EXPECT_EQ(sides[1].sign, 1);
    expect_error([] { tessera::parse_boundary_sides("-x,,+y", "boundary"); }, ErrorKind::option, "boundary:");
}

TEST(OptionText, EnumerationsRoundTripThroughTheirNames) {
    for (auto mode : {tessera::SearchMode::kcoherence, tessera::SearchMode::exhaustive})
        EXPECT_EQ(tessera::parse_search_mode(tessera::to_string(mode), "search"), mode);
    for (auto m : {tessera::Matching::greedy, tessera::Matching::hungarian})
        EXPECT_EQ(tessera::parse_matching(tessera::to_string(m), "matching"), m);
    expect_error([] { tessera::parse_matching("best", "matching"); }, ErrorKind::option, "matching must be greedy");
}

}  // namespace
