// Tests for CSV points (src/io/csv_format.cpp): column rules, grouping rows into
// multi-sample elements, the domain rule, writer -> reader round trips, and one
// test per rejected input asserting the kind and a "FILE:LINE: what" message.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

const std::string source = "data/pts.csv";

// Asserts that parsing `text` throws Error(kind) whose message contains `fragment`
// (which should start with the file and line, e.g. "data/pts.csv:3: ").
void expect_csv_error(const std::string& text, ErrorKind kind, const std::string& fragment,
                      const LoadOptions& options = {}) {
    try {
        parse_csv(text, source, options);
        FAIL() << "no error for: " << text;
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        const std::string message = e.what();
        EXPECT_NE(message.find(source), std::string::npos) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
    }
}

// Same elements, poses and attributes; orientation exact in 3D (written as a
// quaternion) and to rounding in 2D (written as an angle). Types are compared by
// name: CSV has no type table, so a reader numbers types in order of first appearance.
void expect_same_elements(const Exemplar& a, const Exemplar& b) {
    ASSERT_EQ(a.dimension, b.dimension);
    ASSERT_EQ(a.types.size(), b.types.size());
    EXPECT_EQ(a.attribute_names, b.attribute_names);
    ASSERT_EQ(a.elements.size(), b.elements.size());
    for (size_t i = 0; i < a.elements.size(); ++i) {
        const Element& x = a.elements[i];
        const Element& y = b.elements[i];
        EXPECT_EQ(a.types[x.type].name, b.types[y.type].name);
        EXPECT_EQ(x.sample_count, y.sample_count);
        EXPECT_EQ(x.radius, y.radius);
        EXPECT_EQ(x.position, y.position);
        if (a.dimension == 3) {
            EXPECT_EQ(x.orientation, y.orientation);
        } else {
            EXPECT_NEAR(x.orientation.w, y.orientation.w, 1e-15);
            EXPECT_NEAR(x.orientation.z, y.orientation.z, 1e-15);
            EXPECT_EQ(y.orientation.x, 0.0);
            EXPECT_EQ(y.orientation.y, 0.0);
        }
        EXPECT_EQ(x.scale, y.scale);
        EXPECT_EQ(x.attributes, y.attributes);
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.locked, y.locked);
    }
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (size_t s = 0; s < a.samples.size(); ++s) {
        EXPECT_EQ(a.samples[s].p, b.samples[s].p);
        EXPECT_EQ(a.samples[s].sample_id, b.samples[s].sample_id);
        EXPECT_EQ(a.samples[s].time, b.samples[s].time);
    }
}

Exemplar round_trip(const Exemplar& ex) {
    LoadOptions options;
    options.input_domain = ex.domain;  // CSV does not carry the domain
    return parse_csv(to_csv(ex), "round.csv", options);
}

}  // namespace

TEST(IoCsv, ReadsColumnsInAnyOrderCaseInsensitive) {
    const Exemplar ex = parse_csv(
        "Class, Angle ,Y,X,RADIUS\n"
        "rock,0.5,2,1,0.25\n"
        "sand,0,4,3,0.5\n"
        "rock,-1,0,5,1\n",
        source);
    EXPECT_EQ(ex.dimension, 2);
    ASSERT_EQ(ex.elements.size(), 3u);
    ASSERT_EQ(ex.types.size(), 2u);
    EXPECT_EQ(ex.types[0].name, "rock");
    EXPECT_EQ(ex.types[1].name, "sand");
    EXPECT_EQ(ex.elements[2].type, 0);
    EXPECT_EQ(ex.samples[0].p, Vec3(1, 2, 0));
    EXPECT_EQ(ex.elements[0].position, Vec3(1, 2, 0));
    EXPECT_EQ(ex.elements[1].radius, 0.5);
    EXPECT_EQ(ex.elements[0].orientation, Quat::from_angle_z(0.5));
    EXPECT_EQ(ex.elements[2].id, 2u);
    EXPECT_TRUE(ex.attribute_names.empty());
    // Bounding box of the points.
    EXPECT_EQ(ex.domain.bounds().lo, Vec3(1, 0, 0));
    EXPECT_EQ(ex.domain.bounds().hi, Vec3(5, 4, 0));
}

TEST(IoCsv, DefaultsCommentsAndBlankLines) {
    const Exemplar ex = parse_csv(
        "\xEF\xBB\xBF# digitised from photo 3\n"
        "\n"
        "x,y\r\n"
        "0,0\r\n"
        "   # a comment between rows\n"
        "+1.5,2e0\r\n"
        "\n",
        source);
    ASSERT_EQ(ex.types.size(), 1u);
    EXPECT_EQ(ex.types[0].name, "default");
    ASSERT_EQ(ex.elements.size(), 2u);
    EXPECT_EQ(ex.samples[1].p, Vec3(1.5, 2, 0));
    EXPECT_EQ(ex.elements[1].radius, 0.0);
    EXPECT_EQ(ex.elements[1].orientation, Quat{});
}

TEST(IoCsv, IntegerClassesAreNamesAndZMakes3D) {
    const Exemplar ex = parse_csv("x,y,z,class\n0,0,0,2\n1,1,1,10\n2,2,2,2\n", source);
    EXPECT_EQ(ex.dimension, 3);
    EXPECT_EQ(ex.domain.dimension(), 3);
    ASSERT_EQ(ex.types.size(), 2u);
    EXPECT_EQ(ex.types[0].name, "2");
    EXPECT_EQ(ex.types[1].name, "10");
    EXPECT_EQ(ex.elements[2].type, 0);
}

TEST(IoCsv, FreeAttributesAndPoseColumns) {
    const Exemplar ex = parse_csv(
        "x,y,z,hue,qw,qx,qy,qz,scale,Size,id,locked,time\n"
        "0,0,0,0.5,1,0,0,0,2,3,17,1,0.25\n"
        "1,1,1,0.75,0,1,0,0,1,4,3,false,0\n",
        source);
    EXPECT_EQ(ex.attribute_names, (std::vector<std::string>{"hue", "Size"}));
    EXPECT_EQ(ex.elements[0].attributes, (std::vector<double>{0.5, 3}));
    EXPECT_EQ(ex.elements[1].orientation, (Quat{0, 1, 0, 0}));
    EXPECT_EQ(ex.elements[0].scale, 2.0);
    EXPECT_EQ(ex.elements[0].id, 17u);
    EXPECT_EQ(ex.elements[1].id, 3u);
    EXPECT_TRUE(ex.elements[0].locked);
    EXPECT_FALSE(ex.elements[1].locked);
    EXPECT_EQ(ex.samples[0].time, 0.25);
}

TEST(IoCsv, GroupsRowsIntoMultiSampleElements) {
    // Element "b" is interleaved with "a" and its samples are listed out of order.
    const Exemplar ex = parse_csv(
        "element,sample,x,y,class\n"
        "a,0,0,0,stick\n"
        "b,2,5,9,stick\n"
        "a,1,1,0,stick\n"
        "b,0,5,5,stick\n"
        "a,2,2,0,stick\n"
        "b,1,5,7,stick\n",
        source);
    ASSERT_EQ(ex.elements.size(), 2u);
    EXPECT_EQ(ex.elements[0].sample_count, 3);
    EXPECT_EQ(ex.elements[1].sample_count, 3);
    EXPECT_EQ(ex.samples[3].p, Vec3(5, 5, 0));
    EXPECT_EQ(ex.samples[4].p, Vec3(5, 7, 0));
    EXPECT_EQ(ex.samples[5].p, Vec3(5, 9, 0));
    EXPECT_EQ(ex.samples[5].sample_id, 2);
    EXPECT_EQ(ex.elements[0].position, Vec3(1, 0, 0));
    EXPECT_EQ(ex.elements[1].position, Vec3(5, 7, 0));
    // Without a sample column, row order decides.
    const Exemplar by_row = parse_csv("element,x,y\n7,0,0\n7,3,4\n8,1,1\n8,0,0\n", source);
    EXPECT_EQ(by_row.samples[2].p, Vec3(1, 1, 0));
    EXPECT_EQ(by_row.samples[3].p, Vec3(0, 0, 0));
}

TEST(IoCsv, InputDomainOverridesBoundingBox) {
    LoadOptions options;
    options.input_domain = Domain::box({-5, -5, 0}, {5, 5, 0}, 2);
    const Exemplar ex = parse_csv("x,y\n1,1\n", source, options);
    EXPECT_EQ(ex.domain.bounds().lo, Vec3(-5, -5, 0));
    // A single point has a zero-extent bounding box, which is fine with an explicit domain...
    expect_csv_error("x,y\n1,1\n", ErrorKind::domain, "data/pts.csv: the bounding box");
    // ... and all x equal is the same problem along one axis.
    expect_csv_error("x,y\n1,1\n1,2\n", ErrorKind::domain, "along x");
    options.input_domain = Domain::box({0, 0, 0}, {5, 5, 5}, 3);
    expect_csv_error("x,y\n1,1\n", ErrorKind::domain, "the input domain is 3D but the data are 2D", options);
    // A window around none of the points (another axis range) is refused, naming the file.
    options.input_domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    expect_csv_error("x,y\n1,-0.5\n2,-0.7\n", ErrorKind::domain,
                     "data/pts.csv: none of its 2 points lies in the input domain", options);
    // One that leaves some out too: its exemplar would have elements outside its own domain.
    expect_csv_error("x,y\n0.5,0.5\n2,-0.7\n0.2,0.1\n", ErrorKind::domain,
                     "data/pts.csv: 1 of its 3 points lie outside the input domain (the first at 2,-0.7)", options);
    // A point on the window's edge is inside it.
    EXPECT_EQ(parse_csv("x,y\n0,0\n1,1\n0.5,1\n", source, options).elements.size(), 3u);
}

TEST(IoCsv, RoundTripSingleSample2D) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    ex.attribute_names = {"hue", "odd, name"};
    const int rock = ex.type_index("rock");
    const int quoted = ex.type_index("big \"flat\", stone");
    for (int i = 0; i < 20; ++i) {
        const double x = std::fmod(0.618033988749895 * i, 1.0), y = std::fmod(0.7548776662466927 * i, 1.0);
        const int e = ex.add_element(i % 3 ? rock : quoted, {{x, y, 0}}, i % 4 ? 0.01 * i + 1e-13 : 0.0);
        ex.elements[e].orientation = Quat::from_angle_z(0.37 * i - 3.0);
        ex.elements[e].scale = 1.0 / (1 + i);
        ex.elements[e].attributes = {1.0 / 3.0 * i, -1e-200};
        ex.elements[e].id = 100 - static_cast<std::uint64_t>(i);
    }
    ex.elements[3].locked = true;
    ex.samples[5].time = 1.5;
    const Exemplar back = round_trip(ex);
    expect_same_elements(ex, back);
    // The quoted type appears first in the file (element 0), so it becomes type 0.
    EXPECT_EQ(back.types[0].name, "big \"flat\", stone");
    const std::string text = to_csv(ex);
    EXPECT_EQ(text.substr(0, text.find('\n')),
              "x,y,class,radius,angle,scale,id,time,locked,hue,\"odd, name\"");
}

TEST(IoCsv, RoundTrip3DAndMultiSample) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {2, 2, 2}, 3);
    ex.attribute_names = {"age"};
    const int branch = ex.type_index("branch");
    const int leaf = ex.type_index("leaf");
    for (int i = 0; i < 6; ++i) {
        const double o = 0.1 * i + 1.0 / 7.0;
        const int e = ex.add_element(branch, {{o, o, o}, {o + 0.3, o, o + 0.1}, {o + 0.6, o + 0.2, o + 0.3}});
        const double n = std::sqrt(1.0 + 0.04 * i * i + 0.09);
        ex.elements[e].orientation = {1.0 / n, 0.2 * i / n, -0.3 / n, 0.0};
        ex.elements[e].attributes = {static_cast<double>(i)};
        const int l = ex.add_element(leaf, {{1.5, 0.1 * i, 1.0 - 0.1 * i}}, 0.125);
        ex.elements[l].attributes = {0.5};
    }
    ex.update_positions();
    const std::string text = to_csv(ex);
    EXPECT_EQ(text.substr(0, text.find('\n')), "element,sample,x,y,z,class,radius,qw,qx,qy,qz,scale,id,age");
    expect_same_elements(ex, round_trip(ex));
}

TEST(IoCsv, RejectsWrongColumnCount) {
    expect_csv_error("x,y,class\n1,2,a\n\n# comment\n3,4\n", ErrorKind::input,
                     "data/pts.csv:5: expected 3 fields, got 2");
    expect_csv_error("x,y\n1,2,3\n", ErrorKind::input, "data/pts.csv:2: expected 2 fields, got 3");
}

TEST(IoCsv, RejectsNonNumbers) {
    expect_csv_error("x,y\n1,2\n1,2\nabc,4\n", ErrorKind::input, "data/pts.csv:4: x is not a number: 'abc'");
    expect_csv_error("x,y\n1,2\n3,4abc\n", ErrorKind::input, "data/pts.csv:3: y is not a number: '4abc'");
    expect_csv_error("x,y\n1,\n", ErrorKind::input, "data/pts.csv:2: y is not a number: ''");
    expect_csv_error("x,y,hue\n1,2,red\n", ErrorKind::input, "data/pts.csv:2: hue is not a number: 'red'");
    // Without a class column, a text column is most likely class names under another name
    // (spatstat's "marks", a field sheet's "species"): the message says how to read it so.
    expect_csv_error("x,y,marks\n1,2,on\n", ErrorKind::input, "name it 'class' if it holds class names");
    expect_csv_error("x,y,id\n1,2,-1\n", ErrorKind::input,
                     "data/pts.csv:2: id is not a non-negative integer");
    expect_csv_error("x,y,z\n1,2,1e400\n", ErrorKind::input, "data/pts.csv:2: z is not a number");
}

TEST(IoCsv, RejectsNanAndInfinity) {
    expect_csv_error("x,y\n1,2\n0,0\n3,4\n5,6\n7,8\n9,10\n11,12\nnan,1\n", ErrorKind::input,
                     "data/pts.csv:9: coordinate is NaN or infinite");
    expect_csv_error("x,y,z\n1,2,inf\n", ErrorKind::input, "data/pts.csv:2: coordinate is NaN or infinite");
    expect_csv_error("x,y,hue\n1,2,-inf\n", ErrorKind::input, "data/pts.csv:2: hue is NaN or infinite");
}

TEST(IoCsv, RejectsEmptyExemplar) {
    expect_csv_error("", ErrorKind::input, "data/pts.csv: no elements (the exemplar is empty)");
    expect_csv_error("x,y,class\n", ErrorKind::input, "data/pts.csv: no elements (the exemplar is empty)");
    expect_csv_error("# only a comment\n\n", ErrorKind::input,
                     "data/pts.csv: no elements (the exemplar is empty)");
}

TEST(IoCsv, RejectsRadiusNotPositive) {
    expect_csv_error("x,y,radius\n1,2,0.5\n3,4,0\n", ErrorKind::input, "data/pts.csv:3: radius must be > 0");
    expect_csv_error("x,y,radius\n1,2,-0.5\n", ErrorKind::input, "data/pts.csv:2: radius must be > 0");
}

TEST(IoCsv, RejectsBadHeaders) {
    expect_csv_error("x,class\n1,a\n", ErrorKind::input, "data/pts.csv:1: the header needs columns x and y");
    expect_csv_error("# c\nx,y,X\n1,2,3\n", ErrorKind::input, "data/pts.csv:2: duplicate column 'X'");
    expect_csv_error("x,y,,z\n1,2,3,4\n", ErrorKind::input, "data/pts.csv:1: column 3 has no name");
    expect_csv_error("x,y,qw,qx\n1,2,1,0\n", ErrorKind::input, "qw, qx, qy, qz must appear together");
    expect_csv_error("x,y,sample\n1,2,0\n", ErrorKind::input, "needs an element column");
    expect_csv_error("x,y,class\n1,2,\"open\n", ErrorKind::input,
                     "data/pts.csv:2: unterminated quoted field");
}

TEST(IoCsv, RejectsInconsistentElements) {
    expect_csv_error("element,x,y,class\na,0,0,s\na,1,1,t\n", ErrorKind::input,
                     "data/pts.csv:3: element 'a' has a different class than on line 2");
    expect_csv_error("element,sample,x,y\na,0,0,0\na,0,1,1\n", ErrorKind::input,
                     "data/pts.csv:3: element 'a' has sample 0 twice");
    expect_csv_error("element,sample,x,y\na,0.5,0,0\n", ErrorKind::input,
                     "data/pts.csv:2: sample is not an integer");
    expect_csv_error("x,y,id\n0,0,4\n1,1,4\n", ErrorKind::input, "data/pts.csv:3: duplicate element id 4");
    expect_csv_error("x,y,scale\n0,0,0\n", ErrorKind::input, "data/pts.csv:2: scale must be > 0");
    expect_csv_error("x,y,qw,qx,qy,qz\n0,0,0,1,0,0\n", ErrorKind::input,
                     "data/pts.csv:2: in 2D the orientation");
    // Elements of one type must have one sample count (Exemplar::validate names the file).
    expect_csv_error("element,x,y\na,0,0\na,1,1\nb,2,2\n", ErrorKind::input, "different sample counts");
}

TEST(IoCsv, WriterRejectsAttributeNamesThatWouldNotReadBack) {
    Exemplar ex;
    ex.add_element(ex.type_index("a"), {{0, 0, 0}});
    ex.attribute_names = {"Radius"};
    ex.elements[0].attributes = {1};
    EXPECT_THROW(to_csv(ex), Error);
    ex.attribute_names = {"hue", "HUE"};
    ex.elements[0].attributes = {1, 2};
    EXPECT_THROW(to_csv(ex), Error);
}
