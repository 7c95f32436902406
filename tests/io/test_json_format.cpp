// Tests for the native JSON format (src/io/json_format.cpp): lossless round trips in
// 2D and 3D, the defaults of hand-written files, and one test per rejected input
// asserting the error kind and that the message names the file (and JSON path).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

// Asserts that parsing `text` throws Error(kind) whose message contains the source
// name and `fragment`.
void expect_json_error(const std::string& text, ErrorKind kind, const std::string& fragment) {
    const std::string source = "dir/exemplar.json";
    try {
        parse_json(text, source);
        FAIL() << "no error for: " << text;
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        const std::string message = e.what();
        EXPECT_NE(message.find(source), std::string::npos) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
    }
}

// A valid 2D document around the given elements (and optional extra top-level text).
std::string doc2d(const std::string& elements, const std::string& extra = "") {
    return R"({"format": "tessera", "version": 1, "dimension": 2,
               "domain": {"type": "box", "min": [0, 0], "max": [10, 10]},)" +
           extra + R"("elements": [)" + elements + "]}";
}

void expect_same(const Exemplar& a, const Exemplar& b) {
    ASSERT_EQ(a.dimension, b.dimension);
    EXPECT_EQ(a.domain.bounds().lo, b.domain.bounds().lo);
    EXPECT_EQ(a.domain.bounds().hi, b.domain.bounds().hi);
    ASSERT_EQ(a.types.size(), b.types.size());
    for (size_t t = 0; t < a.types.size(); ++t) {
        EXPECT_EQ(a.types[t].name, b.types[t].name);
        EXPECT_EQ(a.types[t].rigid, b.types[t].rigid);
        EXPECT_EQ(a.types[t].floor, b.types[t].floor);
        EXPECT_EQ(a.types[t].mesh, b.types[t].mesh);
        EXPECT_EQ(a.types[t].reference, b.types[t].reference);
    }
    EXPECT_EQ(a.attribute_names, b.attribute_names);
    ASSERT_EQ(a.elements.size(), b.elements.size());
    for (size_t i = 0; i < a.elements.size(); ++i) {
        const Element& x = a.elements[i];
        const Element& y = b.elements[i];
        EXPECT_EQ(x.type, y.type);
        EXPECT_EQ(x.first_sample, y.first_sample);
        EXPECT_EQ(x.sample_count, y.sample_count);
        EXPECT_EQ(x.radius, y.radius);
        EXPECT_EQ(x.position, y.position);
        EXPECT_EQ(x.orientation, y.orientation);  // exact: JSON writes the quaternion itself
        EXPECT_EQ(x.scale, y.scale);
        EXPECT_EQ(x.attributes, y.attributes);
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.locked, y.locked);
    }
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (size_t s = 0; s < a.samples.size(); ++s) {
        EXPECT_EQ(a.samples[s].p, b.samples[s].p);
        EXPECT_EQ(a.samples[s].element, b.samples[s].element);
        EXPECT_EQ(a.samples[s].sample_id, b.samples[s].sample_id);
        EXPECT_EQ(a.samples[s].time, b.samples[s].time);
    }
}

Quat normalized(double w, double x, double y, double z) {
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    return {w / n, x / n, y / n, z / n};
}

// Two types (a 3-sample stick and a single-sample pebble), awkward doubles, attributes,
// non-sequential ids, a lock and time stamps: everything the format carries.
Exemplar rich_exemplar(int dimension) {
    Exemplar ex;
    ex.dimension = dimension;
    ex.domain = dimension == 2 ? Domain::box({-1, 0, 0}, {10.5, 1.0 / 3.0, 0}, 2)
                               : Domain::box({0, 0, -2}, {4, 5, 6.25}, 3);
    const double rz = dimension == 3 ? 0.125 : 0.0;
    ex.types.push_back({"stick", false, false, "meshes/stick.obj", {{-1.0 / 3.0, -0.05, -rz}, {0, 0, 0}, {1.0 / 3.0, 0.05, rz}}, std::nullopt});
    ex.types.push_back({"pebble", true, true, "", {}, std::nullopt});
    ex.attribute_names = {"hue", "wet ness"};
    const double z = dimension == 3 ? 0.7 : 0.0;
    for (int i = 0; i < 4; ++i) {
        const double o = 0.1 * i + 1e-17;
        const int e =
            ex.add_element(0, {{o, 0.2, z}, {o + 1.0 / 3.0, 0.25, z}, {o + 2.0 / 3.0, 0.3 + 1e-9, z}});
        ex.elements[e].orientation =
            dimension == 2 ? Quat::from_angle_z(0.3 * i - 1.0) : normalized(1.0, 0.1 * i, -0.2, 0.3 + i);
        ex.elements[e].scale = 1.0 + 0.125 * i;
        ex.elements[e].attributes = {0.1 * i, -2.5e-300};
        ex.elements[e].id = 1000 + 7 * static_cast<std::uint64_t>(i);
    }
    for (int i = 0; i < 3; ++i) {
        const int e = ex.add_element(1, {{3.0 + std::sqrt(2.0) * i, 0.1, z * i}}, 0.05 + 0.01 * i);
        ex.elements[e].attributes = {1.0 / 7.0, static_cast<double>(i)};
        ex.elements[e].id = 5 - static_cast<std::uint64_t>(i);
    }
    ex.elements[1].locked = true;
    ex.samples[ex.elements[2].first_sample + 1].time = 0.5;  // differing times within one element
    for (int s = 0; s < 1; ++s) ex.samples[ex.elements[5].first_sample + s].time = 2.75;
    ex.update_positions();
    ex.validate("rich");
    return ex;
}

}  // namespace

TEST(IoJson, RoundTrip2DIsExact) {
    const Exemplar ex = rich_exemplar(2);
    const Exemplar back = parse_json(to_json(ex), "round.json");
    expect_same(ex, back);
}

TEST(IoJson, RoundTrip3DIsExact) {
    const Exemplar ex = rich_exemplar(3);
    const std::string text = to_json(ex);
    const Exemplar back = parse_json(text, "round.json");
    expect_same(ex, back);
    // Writing the re-read data gives the same text: nothing drifts over repeated saves.
    EXPECT_EQ(to_json(back), text);
}

TEST(IoJson, WritesTheDocumentedFields) {
    const std::string text = to_json(rich_exemplar(2));
    for (const char* fragment :
         {"\"format\": \"tessera\"", "\"version\": 1", "\"dimension\": 2", "\"type\":\"box\"",
          "\"min\":[-1.0,0.0]", "\"samples\":[[", "\"position\":[", "\"angle\":", "\"orientation\":[",
          "\"scale\":", "\"radius\":0.05", "\"attributes\": [\"hue\",\"wet ness\"]", "\"locked\":true",
          "\"time\":2.75", "\"time\":[0.0,0.5,0.0]", "\"id\":1000", "\"mesh\":\"meshes/stick.obj\"",
          "\"reference\":[[-0.3333333333333333,-0.05],[0.0,0.0],[0.3333333333333333,0.05]]"})
        EXPECT_NE(text.find(fragment), std::string::npos) << fragment << "\n" << text;
    EXPECT_EQ(text.find("\"stats\""), std::string::npos);
}

TEST(IoJson, ArrangementStatsAreWrittenAndIgnoredOnRead) {
    Arrangement a;
    static_cast<Exemplar&>(a) = rich_exemplar(2);
    a.stats.method = "det";
    a.stats.energy = {3.5, 2.25, 2.0};
    a.stats.iteration_seconds = {0.1, 0.2, 0.3};
    a.stats.total_seconds = 0.75;
    a.stats.threads = 2;
    a.stats.seed = 18446744073709551615ull;
    a.stats.fallbacks = 3;
    a.stats.notes = {"grid search placed 3 of 8 elements", "a \"quoted\" note"};
    const std::string text = to_json(a, &a.stats);
    for (const char* fragment : {"\"stats\":", "\"method\":\"det\"", "\"energy\":[3.5,2.25,2.0]",
                                 "\"seed\":18446744073709551615", "\"fallbacks\":3",
                                 "\"notes\":[\"grid search placed 3 of 8 elements\",\"a \\\"quoted\\\" note\"]"})
        EXPECT_NE(text.find(fragment), std::string::npos) << fragment << "\n" << text;
    // Timings and the thread count vary between runs of the same synthesis: not written.
    for (const char* fragment : {"seconds", "\"threads\""})
        EXPECT_EQ(text.find(fragment), std::string::npos) << fragment << "\n" << text;
    expect_same(a, parse_json(text, "out.json"));
}

TEST(IoJson, HandWrittenDefaults) {
    // No "types": types are created in order of first appearance; ids default to the index.
    const Exemplar ex = parse_json(doc2d(R"({"type": "b", "samples": [[0, 0], [2, 0]]},
                                            {"type": "a", "position": [3, 4], "angle": 0.5, "radius": 0.25},
                                            {"type": "b", "samples": [[1, 1], [3, 1]], "id": 9},
                                            {"type": "b", "samples": [[5, 5], [5, 7]]})"),
                                   "hand.json");
    ASSERT_EQ(ex.types.size(), 2u);
    EXPECT_EQ(ex.types[0].name, "b");
    EXPECT_EQ(ex.types[1].name, "a");
    EXPECT_TRUE(ex.types[0].rigid);
    EXPECT_FALSE(ex.types[0].floor);
    EXPECT_EQ(ex.types[0].mesh, "");
    ASSERT_EQ(ex.elements.size(), 4u);
    EXPECT_EQ(ex.elements[1].type, 1);
    EXPECT_EQ(ex.elements[0].id, 0u);
    EXPECT_EQ(ex.elements[1].id, 1u);
    EXPECT_EQ(ex.elements[2].id, 9u);
    EXPECT_EQ(ex.elements[3].id, 3u);
    EXPECT_EQ(ex.elements[0].radius, 0.0);
    EXPECT_EQ(ex.elements[1].radius, 0.25);
    EXPECT_EQ(ex.elements[0].orientation, Quat{});
    EXPECT_EQ(ex.elements[1].orientation, Quat::from_angle_z(0.5));
    EXPECT_EQ(ex.elements[0].scale, 1.0);
    EXPECT_FALSE(ex.elements[0].locked);
    EXPECT_TRUE(ex.attribute_names.empty());
    EXPECT_EQ(ex.elements[2].sample_count, 2);
    EXPECT_EQ(ex.elements[2].position, Vec3(2, 1, 0));  // centroid
    EXPECT_EQ(ex.samples[ex.elements[3].first_sample + 1].sample_id, 1);
    EXPECT_EQ(ex.samples[ex.elements[3].first_sample + 1].p, Vec3(5, 7, 0));
    EXPECT_EQ(ex.samples[ex.elements[3].first_sample + 1].time, 0.0);
    EXPECT_EQ(ex.domain.bounds().hi, Vec3(10, 10, 0));
}

TEST(IoJson, TypeMayBeOmittedWhenUnambiguous) {
    const Exemplar declared = parse_json(
        doc2d(R"({"position": [1, 2]})", R"("types": [{"name": "pebble", "floor": true}],)"), "t.json");
    EXPECT_EQ(declared.types.size(), 1u);
    EXPECT_TRUE(declared.types[0].floor);
    const Exemplar undeclared = parse_json(doc2d(R"({"position": [1, 2]})"), "t.json");
    EXPECT_EQ(undeclared.types[0].name, "default");
    expect_json_error(doc2d(R"({"position": [1, 2]})", R"("types": [{"name": "a"}, {"name": "b"}],)"),
                      ErrorKind::input, "elements[0]: missing \"type\"");
}

TEST(IoJson, HandTypedQuaternionIsNormalised) {
    const Exemplar ex =
        parse_json(doc2d(R"({"position": [1, 2], "orientation": [0.7071, 0, 0, 0.7071]})"), "q.json");
    const Quat& q = ex.elements[0].orientation;
    EXPECT_NEAR(q.w * q.w + q.z * q.z, 1.0, 1e-15);
    EXPECT_NEAR(q.angle_z(), std::numbers::pi / 2, 1e-12);
}

TEST(IoJson, MalformedJsonNamesFileAndLine) {
    expect_json_error("{\"format\": \"tessera\",\n \"version\": 1,,\n}", ErrorKind::input, "line 2");
    expect_json_error("", ErrorKind::input, "invalid JSON");
    expect_json_error(doc2d(R"({"position": [1e400, 2]})"), ErrorKind::input, "invalid JSON");
    expect_json_error("[1, 2]", ErrorKind::input, "must be a JSON object");
}

TEST(IoJson, RejectsWrongFormatAndVersion) {
    expect_json_error(R"({"format": "other", "version": 1, "dimension": 2})", ErrorKind::input,
                      "not a tessera file");
    expect_json_error(R"({"version": 1, "dimension": 2})", ErrorKind::input, "missing \"format\"");
    expect_json_error(R"({"format": "tessera", "version": 2, "dimension": 2})", ErrorKind::input,
                      "unsupported version 2");
    expect_json_error(R"({"format": "tessera", "version": 1, "dimension": 4})", ErrorKind::input,
                      "dimension: must be 2 or 3");
}

TEST(IoJson, RejectsUnknownElementType) {
    expect_json_error(doc2d(R"({"type": "stick", "position": [1, 2]}, {"type": "rock", "position": [1, 3]})",
                            R"("types": [{"name": "stick"}],)"),
                      ErrorKind::input, "elements[1]: unknown element type 'rock'");
}

TEST(IoJson, RejectsEmptyExemplar) {
    expect_json_error(doc2d(""), ErrorKind::input, "no elements (the exemplar is empty)");
}

TEST(IoJson, RejectsZeroOrNegativeDomain) {
    const std::string element = R"("elements": [{"position": [1, 2]}]})";
    expect_json_error(
        R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [0, 5]},)" +
            element,
        ErrorKind::domain, "extent along x");
    expect_json_error(
        R"({"format": "tessera", "version": 1, "dimension": 3, "domain": {"type": "box", "min": [0, 0, 5], "max": [1, 1, 4]},)" +
            element,
        ErrorKind::domain, "extent along z");
}

TEST(IoJson, RejectsBadDomainShape) {
    expect_json_error(
        R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "disk", "min": [0, 0], "max": [1, 1]}, "elements": []})",
        ErrorKind::input, "unsupported domain type 'disk'");
    expect_json_error(
        R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]}, "elements": []})",
        ErrorKind::input, "domain.min: must be an array of 2 numbers");
    expect_json_error(R"({"format": "tessera", "version": 1, "dimension": 2, "elements": []})",
                      ErrorKind::input, "missing \"domain\"");
}

TEST(IoJson, RejectsBadElements) {
    expect_json_error(doc2d(R"({"position": [1, 2], "radius": -1})"), ErrorKind::input, "elements[0].radius");
    expect_json_error(doc2d(R"({"position": [1, 2], "raduis": 1})"), ErrorKind::input,
                      "unknown key 'raduis'");
    expect_json_error(doc2d(R"({"position": [1, 2], "samples": [[1, 2]]})"), ErrorKind::input,
                      "exactly one of");
    expect_json_error(doc2d(R"({"type": "a"})"), ErrorKind::input, "exactly one of");
    expect_json_error(doc2d(R"({"position": [1, 2, 3]})"), ErrorKind::input,
                      "elements[0].position: must be an array of 2");
    expect_json_error(doc2d(R"({"position": [1, "2"]})"), ErrorKind::input, "elements[0].position");
    expect_json_error(doc2d(R"({"samples": []})"), ErrorKind::input,
                      "elements[0].samples: must not be empty");
    expect_json_error(doc2d(R"({"position": [1, 2], "scale": 0})"), ErrorKind::input,
                      "elements[0].scale: must be > 0");
    expect_json_error(doc2d(R"({"position": [1, 2], "id": -3})"), ErrorKind::input, "non-negative integer");
    expect_json_error(doc2d(R"({"position": [1, 2], "id": 1}, {"position": [2, 2]})"), ErrorKind::input,
                      "elements[1]: duplicate element id 1");
    expect_json_error(doc2d(R"({"position": [1, 2], "locked": 1})"), ErrorKind::input, "elements[0].locked");
    expect_json_error(doc2d(R"({"position": [1, 2], "orientation": [0, 1, 0, 0]})"), ErrorKind::input,
                      "rotation about z");
    expect_json_error(doc2d(R"({"position": [1, 2], "orientation": [0, 0, 0, 0]})"), ErrorKind::input,
                      "zero quaternion");
    expect_json_error(doc2d(R"({"position": [1, 2], "orientation": [1, 0, 0, 0], "angle": 1})"),
                      ErrorKind::input, "different rotations");
    expect_json_error(doc2d(R"({"samples": [[1, 2], [2, 2]], "time": [1, 2, 3]})"), ErrorKind::input,
                      "elements[0].time");
    // Elements of one type must have the same number of samples (checked by Exemplar::validate).
    expect_json_error(doc2d(R"({"samples": [[1, 2], [2, 2]]}, {"samples": [[1, 2], [2, 2], [3, 3]]})"),
                      ErrorKind::input, "different sample counts");
}

TEST(IoJson, RejectsBadTypesAndAttributes) {
    expect_json_error(doc2d(R"({"position": [1, 2]})", R"("types": [{"rigid": true}],)"), ErrorKind::input,
                      "types[0]: missing \"name\"");
    expect_json_error(
        doc2d(R"({"type": "a", "position": [1, 2]})", R"("types": [{"name": "a"}, {"name": "a"}],)"),
        ErrorKind::input, "defined twice");
    expect_json_error(doc2d(R"({"position": [1, 2]})", R"("attributes": ["hue"],)"), ErrorKind::input,
                      "elements[0]: missing \"attributes\"");
    expect_json_error(doc2d(R"({"position": [1, 2], "attributes": [1, 2]})", R"("attributes": ["hue"],)"),
                      ErrorKind::input, "elements[0].attributes: must be an array of 1");
    expect_json_error(doc2d(R"({"position": [1, 2], "attributes": [1]})"), ErrorKind::input,
                      "elements[0].attributes: must be an array of 0");
    expect_json_error(doc2d(R"({"position": [1, 2]})", R"("extra": 1,)"), ErrorKind::input,
                      "unknown key 'extra'");
}

TEST(IoJson, TypeReferenceLayout) {
    const std::string types = R"("types": [{"name": "s", "mesh": "s.obj", "reference": [[-1, 0], [1, 0]]}],)";
    const Exemplar ex = parse_json(doc2d(R"({"samples": [[1, 2], [3, 2]]})", types), "r.json");
    ASSERT_EQ(ex.types[0].reference.size(), 2u);
    EXPECT_EQ(ex.types[0].reference[1], Vec3(1, 0, 0));
    // A type without one writes no "reference" key.
    EXPECT_EQ(to_json(parse_json(doc2d(R"({"position": [1, 2]})"), "r.json")).find("reference"), std::string::npos);

    const auto with_reference = [](const std::string& reference) {
        return doc2d(R"({"samples": [[1, 2], [3, 2]]})",
                     R"("types": [{"name": "s", "reference": )" + reference + "}],");
    };
    expect_json_error(with_reference("[[0, 0], [1, 0], [2, 0]]"), ErrorKind::input,
                      "element type 's' has a reference layout of 3 samples but its elements have 2");
    expect_json_error(with_reference("[[0, 0, 0], [1, 0, 0]]"), ErrorKind::input,
                      "types[0].reference[0]: must be an array of 2 numbers");
    expect_json_error(with_reference(R"([[0, 0], [1, "x"]])"), ErrorKind::input, "types[0].reference[1]");
    expect_json_error(with_reference(R"({"a": 1})"), ErrorKind::input, "types[0].reference: must be an array");
}
