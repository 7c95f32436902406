// Tests for parse_box_domain (src/io/box_domain.cpp): 4 values give a 2D box, 6 a 3D
// box; everything else is Error(option) naming the parameter.
#include <gtest/gtest.h>

#include <string>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

void expect_option_error(const std::string& text, const std::string& fragment) {
    try {
        parse_box_domain(text, "--input-domain");
        FAIL() << "no error for '" << text << "'";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option) << e.what();
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("--input-domain: ", 0), 0u) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
    }
}

}  // namespace

TEST(IoBoxDomain, TwoAndThreeDimensions) {
    const Domain d2 = parse_box_domain("0,1,10,21", "--domain");
    EXPECT_EQ(d2.dimension(), 2);
    EXPECT_EQ(d2.bounds().lo, Vec3(0, 1, 0));
    EXPECT_EQ(d2.bounds().hi, Vec3(10, 21, 0));
    const Domain d3 = parse_box_domain(" -1 , -2, 3.5 ,4e0, -5, +6 ", "--domain");
    EXPECT_EQ(d3.dimension(), 3);
    EXPECT_EQ(d3.bounds().lo, Vec3(-1, -2, -5));
    EXPECT_EQ(d3.bounds().hi, Vec3(3.5, 4, 6));
}

TEST(IoBoxDomain, RejectsWrongCountsNonNumbersAndEmptyBoxes) {
    expect_option_error("0,0,1", "got 3 values");
    expect_option_error("0,0,1,1,2", "got 5 values");
    expect_option_error("", "is not a number");
    expect_option_error("0,0,1,one", "'one' is not a number");
    expect_option_error("0,0,1,,1", "'' is not a number");
    expect_option_error("0,0,nan,1", "finite");
    expect_option_error("0,0,0,1", "extent along x");
    expect_option_error("0,5,1,1", "extent along y");
    expect_option_error("0,0,1,1,3,3", "extent along z");
}
