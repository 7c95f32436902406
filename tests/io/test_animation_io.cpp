// Tests for animations in files (src/io/animation_json.cpp, animation_csv.cpp,
// animation_files.cpp): JSON and CSV round trips with bit-exact positions, load() of an
// animated file giving frame 0, has_frames, static files as one-frame animations, and one
// test per rejected input asserting Error(input) and a one-line message naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "tessera/animation.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

// Particles (automatic), a thread and a sheet of 2 x 3 samples, through 3 frames whose
// coordinates and times are not short decimals, so that round trips must be exact.
Animation test_animation(int dimension) {
    Exemplar ex;
    ex.dimension = dimension;
    ex.domain =
        Domain::box({-5, -5, dimension == 3 ? -5.0 : 0.0}, {20, 20, dimension == 3 ? 20.0 : 0.0}, dimension);
    ex.attribute_names = {"hue"};
    const int dot = ex.type_index("dot");
    const int noodle = ex.type_index("noodle");
    const int cloth = ex.type_index("cloth");
    ex.types[noodle].topology = ElementTopology::thread;
    ex.types[noodle].rigid = false;
    ex.types[cloth].topology = ElementTopology::sheet;
    ex.types[cloth].sheet_columns = 3;
    ex.types[dot].glyph = ElementGlyph::fish;
    const double z = dimension == 3 ? 0.7 : 0.0;
    ex.add_element(dot, {{1.0 / 3, 2, z}}, 0.25);
    ex.add_element(dot, {{4, 1.0 / 7, z}}, 0.5);
    ex.add_element(noodle, {{1, 5, z}, {2, 5.5, z}, {3, 6, z}});
    std::vector<Vec3> grid;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) grid.push_back({6.0 + c, 6.0 + r, dimension == 3 ? z + 0.1 * r : 0.0});
    ex.add_element(cloth, grid);
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        ex.elements[i].id = 100 + 7 * i;
        ex.elements[i].attributes = {0.1 * static_cast<double>(i)};
    }
    ex.elements[1].locked = true;
    ex.elements[0].orientation = dimension == 3 ? Quat{0.5, 0.5, 0.5, 0.5} : Quat::from_angle_z(0.3);
    Animation a = animation_from_exemplar(ex, 0.1);
    for (int f = 1; f < 3; ++f) {
        std::vector<Vec3> p;
        for (const Sample& s : ex.samples) p.push_back(s.p + Vec3{0.1 * f, std::sin(f + s.p.x), z / 3 * f});
        a.add_frame(0.1 + f / 3.0, p);
    }
    a.validate("test");
    return a;
}

// Same structure, times and positions (bit-exact). Orientation exact unless `angle_only`
// (2D CSV writes the angle, which comes back to rounding); type flags other than the name
// only when `types_exact` (CSV does not carry them).
void expect_same_animation(const Animation& a, const Animation& b, bool types_exact,
                           bool angle_only = false) {
    ASSERT_EQ(a.structure.dimension, b.structure.dimension);
    EXPECT_EQ(a.times, b.times);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t i = 0; i < a.positions.size(); ++i)
        EXPECT_EQ(a.positions[i], b.positions[i]) << "position " << i;
    EXPECT_EQ(a.structure.attribute_names, b.structure.attribute_names);
    ASSERT_EQ(a.structure.types.size(), b.structure.types.size());
    for (size_t t = 0; t < a.structure.types.size() && types_exact; ++t) {
        EXPECT_EQ(a.structure.types[t].name, b.structure.types[t].name);
        EXPECT_EQ(a.structure.types[t].rigid, b.structure.types[t].rigid);
        EXPECT_EQ(a.structure.types[t].topology, b.structure.types[t].topology);
        EXPECT_EQ(a.structure.types[t].sheet_columns, b.structure.types[t].sheet_columns);
        EXPECT_EQ(a.structure.types[t].glyph, b.structure.types[t].glyph);
    }
    ASSERT_EQ(a.structure.elements.size(), b.structure.elements.size());
    for (size_t i = 0; i < a.structure.elements.size(); ++i) {
        const Element& x = a.structure.elements[i];
        const Element& y = b.structure.elements[i];
        EXPECT_EQ(a.structure.types[x.type].name, b.structure.types[y.type].name);
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.sample_count, y.sample_count);
        EXPECT_EQ(x.first_sample, y.first_sample);
        EXPECT_EQ(x.radius, y.radius);
        EXPECT_EQ(x.scale, y.scale);
        EXPECT_EQ(x.attributes, y.attributes);
        EXPECT_EQ(x.locked, y.locked);
        if (angle_only) {
            EXPECT_NEAR(x.orientation.angle_z(), y.orientation.angle_z(), 1e-15);
        } else {
            EXPECT_EQ(x.orientation, y.orientation);
        }
    }
    for (const Sample& s : b.structure.samples) EXPECT_EQ(s.time, b.times.front());
}

LoadOptions domain_of(const Animation& a) {
    LoadOptions options;
    options.input_domain = a.structure.domain;  // CSV does not carry the domain
    return options;
}

// Asserts that `parse` throws Error(input) with a one-line message naming `source` and
// containing `fragment`.
void expect_input_error(const std::function<void()>& parse, const std::string& source,
                        const std::string& fragment) {
    try {
        parse();
        FAIL() << "no error, expected: " << fragment;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.kind(), ErrorKind::input) << message;
        EXPECT_EQ(message.rfind(source, 0), 0u) << "does not start with the file: " << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
    }
}

const std::string json_source = "dir/anim.json";
const std::string csv_source = "dir/anim.csv";

void expect_json_error(const std::string& text, const std::string& fragment) {
    expect_input_error([&] { parse_animation_json(text, json_source); }, json_source, fragment);
    // load() and parse_json read animated files too, and must reject the same.
    expect_input_error([&] { parse_json(text, json_source); }, json_source, fragment);
}

void expect_csv_error(const std::string& text, const std::string& fragment) {
    expect_input_error([&] { parse_animation_csv(text, csv_source); }, csv_source, fragment);
    expect_input_error([&] { parse_csv(text, csv_source); }, csv_source, fragment);
}

// A 2D animated document with the given types, element definitions and frames.
std::string animated(const std::string& types, const std::string& elements, const std::string& frames) {
    return R"({"format": "tessera", "version": 1, "dimension": 2,
               "domain": {"type": "box", "min": [0, 0], "max": [10, 10]},
               "types": [)" +
           types + R"(], "elements": [)" + elements + R"(], "frames": [)" + frames + "]}";
}

// Two dots (ids 1, 2) in two frames.
const std::string dot_types = R"({"name": "dot"})";
const std::string dot_elements = R"({"id": 1}, {"id": 2})";
std::string dot_frame(double time, const std::string& extra = "") {
    return R"({"time": )" + std::to_string(time) +
           R"(, "elements": [{"id": 1, "position": [1, 1]}, {"id": 2, "position": [2, 2]})" + extra + "]}";
}

}  // namespace

TEST(IoAnimationJson, RoundTrip2DAnd3D) {
    for (const int dimension : {2, 3}) {
        const Animation a = test_animation(dimension);
        const std::string text = animation_to_json(a);
        const Animation b = parse_animation_json(text, "round.json");
        expect_same_animation(a, b, true);
        EXPECT_EQ(animation_to_json(b), text) << "writing it again changes the file";
    }
}

TEST(IoAnimationJson, WritesDefinitionsAndOneFrameElementPerLine) {
    const Animation a = test_animation(2);
    const std::string text = animation_to_json(a);
    EXPECT_NE(text.find(R"({"name":"noodle","rigid":false,"floor":false,"mesh":"","topology":"thread"})"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"("topology":"sheet","columns":3})"), std::string::npos) << text;
    EXPECT_EQ(text.find(R"({"name":"dot","rigid":true,"floor":false,"mesh":"","topology)"), std::string::npos)
        << "automatic topology is not written";
    EXPECT_NE(text.find(R"(    {"id":100,"type":"dot","radius":0.25,"angle":)"), std::string::npos) << text;
    EXPECT_NE(text.find("\n    {\"time\": 0.1, \"elements\": [\n      {\"id\":100,\"position\":["),
              std::string::npos)
        << text;
    size_t lines = 0;
    for (size_t at = text.find("\n    {\"id\":"); at != std::string::npos;
         at = text.find("\n    {\"id\":", at + 1))
        ++lines;
    size_t frame_lines = 0;
    for (size_t at = text.find("\n      {\"id\":"); at != std::string::npos;
         at = text.find("\n      {\"id\":", at + 1))
        ++frame_lines;
    EXPECT_EQ(lines, a.structure.elements.size());
    EXPECT_EQ(frame_lines, a.structure.elements.size() * a.times.size());
    // The definitions carry no positions, the frame elements nothing but them.
    for (size_t at = text.find("\n    {\"id\":"); at != std::string::npos;
         at = text.find("\n    {\"id\":", at + 1)) {
        const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
        EXPECT_EQ(line.find("position"), std::string::npos) << line;
        EXPECT_EQ(line.find("samples"), std::string::npos) << line;
    }
    // The last element of frame 0 (the sheet), and the end of the frame.
    const std::string sheet =
        R"({"id":121,"samples":[[6.0,6.0],[7.0,6.0],[8.0,6.0],[6.0,7.0],[7.0,7.0],[8.0,7.0]]})";
    EXPECT_NE(text.find("\n      " + sheet + "\n    ]},\n"), std::string::npos) << text;
}

TEST(IoAnimationJson, StatsAreWrittenAndIgnoredOnReading) {
    const Animation a = test_animation(2);
    RunStats stats;
    stats.method = "dynamic";
    stats.energy = {2.5, 1.25};
    stats.seed = 7;
    const std::string text = animation_to_json(a, &stats);
    EXPECT_NE(text.find("  ],\n  \"stats\": " + run_stats_json(stats) + "\n}\n"), std::string::npos) << text;
    expect_same_animation(a, parse_animation_json(text, "stats.json"), true);
}

TEST(IoAnimationJson, LoadAndParseJsonGiveFrameZero) {
    const Animation a = test_animation(3);
    const Exemplar frame0 = parse_json(animation_to_json(a), "anim.json");
    const Exemplar expected = a.frame(0);
    ASSERT_EQ(frame0.samples.size(), expected.samples.size());
    for (size_t s = 0; s < expected.samples.size(); ++s) {
        EXPECT_EQ(frame0.samples[s].p, expected.samples[s].p);
        EXPECT_EQ(frame0.samples[s].time, a.times[0]);
    }
    ASSERT_EQ(frame0.elements.size(), expected.elements.size());
    for (size_t i = 0; i < expected.elements.size(); ++i)
        EXPECT_EQ(frame0.elements[i].id, expected.elements[i].id);
    EXPECT_EQ(frame0.types[2].topology, ElementTopology::sheet);
    EXPECT_EQ(frame0.types[2].sheet_columns, 3);
}

TEST(IoAnimationJson, StaticDocumentsKeepTopologyAndColumns) {
    const Exemplar ex = test_animation(2).frame(0);
    const std::string text = to_json(ex);
    const Exemplar back = parse_json(text, "static.json");
    EXPECT_EQ(back.types[1].topology, ElementTopology::thread);
    EXPECT_EQ(back.types[2].topology, ElementTopology::sheet);
    EXPECT_EQ(back.types[2].sheet_columns, 3);
    EXPECT_EQ(to_json(back), text);
}

TEST(IoAnimationJson, HandWrittenFramesAndDefaults) {
    const Animation a = parse_animation_json(
        animated(R"({"name": "stick", "topology": "thread"})",
                 R"({"id": 5, "type": "stick", "radius": 0.1}, {"id": 3, "type": "stick"})",
                 R"({"time": 0, "elements": [{"id": 3, "samples": [[1, 1], [2, 1]]},
                                             {"id": 5, "samples": [[4, 4], [5, 4]]}]},
                    {"time": 2, "elements": [{"id": 5, "samples": [[4, 5], [5, 5]]},
                                             {"id": 3, "samples": [[1, 2], [2, 2]]}]})"),
        json_source);
    ASSERT_EQ(a.frame_count(), 2);
    EXPECT_EQ(a.times, (std::vector<double>{0, 2}));
    // Elements in the order of "elements", matched by id in every frame.
    EXPECT_EQ(a.structure.elements[0].id, 5u);
    EXPECT_EQ(a.structure.elements[0].radius, 0.1);
    EXPECT_EQ(a.at(0, 0), (Vec3{4, 4, 0}));
    EXPECT_EQ(a.at(1, 0), (Vec3{4, 5, 0}));
    EXPECT_EQ(a.at(1, 3), (Vec3{2, 2, 0}));
    EXPECT_EQ(a.structure.elements[1].position, (Vec3{1.5, 1, 0}));  // frame 0's centroid
}

TEST(IoAnimationJson, RejectsDifferentElementSets) {
    expect_json_error(
        animated(dot_types, dot_elements,
                 dot_frame(0) + "," + dot_frame(1) + "," +
                     R"({"time": 2, "elements": [{"id": 1, "position": [1, 1]}]})"),
        "dir/anim.json: frames[2]: element id 2 is missing (every frame must hold the same elements)");
    expect_json_error(animated(dot_types, dot_elements,
                               dot_frame(0) + "," + dot_frame(1, R"(, {"id": 9, "position": [3, 3]})")),
                      "frames[1].elements[2]: element id 9 is not in frames[0]");
    expect_json_error(animated(dot_types, dot_elements, dot_frame(0, R"(, {"id": 9, "position": [3, 3]})")),
                      "frames[0].elements[2]: element id 9 is not defined in \"elements\"");
    expect_json_error(animated(dot_types, dot_elements + R"(, {"id": 4})", dot_frame(0)),
                      "elements[2]: element id 4 is in no frame");
    expect_json_error(animated(dot_types, dot_elements, dot_frame(0, R"(, {"id": 2, "position": [3, 3]})")),
                      "frames[0].elements[2]: element id 2 appears twice in the frame");
}

TEST(IoAnimationJson, RejectsDifferentSamplesAcrossFrames) {
    const std::string types = R"({"name": "stick"})";
    const std::string frame0 = R"({"time": 0, "elements": [{"id": 1, "samples": [[1, 1], [2, 1]]}]})";
    expect_json_error(
        animated(types, R"({"id": 1})",
                 frame0 + R"(, {"time": 1, "elements": [{"id": 1, "samples": [[1, 1], [2, 1], [3, 1]]}]})"),
        "frames[1].elements[0]: element id 1 has 3 samples here but 2 in frames[0]");
    expect_json_error(
        animated(dot_types, dot_elements,
                 dot_frame(0) + R"(, {"time": 1, "elements": [{"id": 1, "samples": [[1, 1]]},
                                                                           {"id": 2, "position": [2, 2]}]})"),
        "frames[1].elements[0]: element id 1 has \"samples\" here but \"position\" in frames[0]");
}

TEST(IoAnimationJson, RejectsTimeStampsThatDoNotIncrease) {
    expect_json_error(
        animated(dot_types, dot_elements, dot_frame(0) + "," + dot_frame(1) + "," + dot_frame(1)),
        "dir/anim.json: frames[2].time: time stamps must strictly increase");
    expect_json_error(animated(dot_types, dot_elements, dot_frame(1) + "," + dot_frame(0.5)),
                      "frames[1].time: time stamps must strictly increase");
    expect_json_error(animated(dot_types, dot_elements, R"({"elements": []})"),
                      "frames[0]: missing \"time\"");
}

TEST(IoAnimationJson, RejectsUnknownAndMisplacedKeys) {
    expect_json_error(
        animated(dot_types, dot_elements,
                 dot_frame(0) + R"(, {"time": 1, "elements": [{"id": 1, "position": [1, 1], "radius": 2},
                                                                           {"id": 2, "position": [2, 2]}]})"),
        "dir/anim.json: frames[1].elements[0]: unknown key 'radius'");
    expect_json_error(animated(dot_types, dot_elements, R"({"time": 0, "when": 1, "elements": []})"),
                      "frames[0]: unknown key 'when'");
    expect_json_error(animated(dot_types, R"({"id": 1, "position": [1, 1]}, {"id": 2})", dot_frame(0)),
                      "elements[0].position: not allowed in an animated file");
    expect_json_error(animated(dot_types, R"({"id": 1}, {"type": "dot"})", dot_frame(0)),
                      "elements[1]: missing \"id\" (required in an animated file");
    expect_json_error(animated(R"({"name": "dot", "topology": "rope"})", dot_elements, dot_frame(0)),
                      "types[0].topology: unknown topology 'rope'");
    expect_json_error(animated(R"({"name": "dot", "glyph": "whale"})", dot_elements, dot_frame(0)),
                      "types[0].glyph: unknown glyph 'whale' (known: disk, fish)");
    expect_json_error(animated(dot_types, dot_elements, "{}"), "frames[0]: missing \"time\"");
    expect_json_error(animated(dot_types, dot_elements, ""), "frames: must hold at least one frame");
}

TEST(IoAnimationJson, RejectsTopologiesTheElementsDoNotHave) {
    const std::string frame0 =
        R"({"time": 0, "elements": [{"id": 1, "samples": [[1, 1], [2, 1], [3, 1], [1, 2], [2, 2], [3, 2]]}]})";
    expect_json_error(
        animated(R"({"name": "cloth", "topology": "sheet", "columns": 4})", R"({"id": 1})", frame0),
        "dir/anim.json: type 'cloth' is a sheet but its 6 samples are not a grid of 4 columns");
    expect_json_error(animated(R"({"name": "cloth", "topology": "sheet"})", R"({"id": 1})", frame0),
                      "type 'cloth' is a sheet");
    expect_json_error(animated(R"({"name": "dot", "topology": "thread"})", dot_elements, dot_frame(0)),
                      "type 'dot' is a thread but its elements have 1 sample");
    EXPECT_EQ(parse_animation_json(
                  animated(R"({"name": "cloth", "topology": "sheet", "columns": 3})", R"({"id": 1})", frame0),
                  json_source)
                  .structure.types[0]
                  .sheet_columns,
              3);
}

TEST(IoAnimationCsv, RoundTripWithFrameColumn2DAnd3D) {
    for (const int dimension : {2, 3}) {
        const Animation a = test_animation(dimension);
        const std::string text = animation_to_csv(a);
        EXPECT_EQ(
            text.rfind(dimension == 2
                           ? "frame,time,element,sample,x,y,class,radius,angle,scale,id,locked,hue\n"
                           : "frame,time,element,sample,x,y,z,class,radius,qw,qx,qy,qz,scale,id,locked,hue\n",
                       0),
            0u)
            << text;
        const Animation b = parse_animation_csv(text, "round.csv", domain_of(a));
        expect_same_animation(a, b, false, dimension == 2);
        EXPECT_EQ(b.structure.types[1].name, "noodle");
        // (In 2D the orientation goes through its angle, which need not come back to the bit.)
        if (dimension == 3) {
            EXPECT_EQ(animation_to_csv(b), text) << "writing it again changes the file";
        }
    }
}

TEST(IoAnimationCsv, TColumnRowsInAnyOrder) {
    const Animation a = parse_animation_csv(
        "t,element,sample,x,y,class\n"
        "2.5,b,0,9,9,dot\n"
        "0.5,w,1,2,1,worm\n"
        "0.5,b,0,5,5,dot\n"
        "2.5,w,0,1,2,worm\n"
        "0.5,w,0,1,1,worm\n"
        "2.5,w,1,2,2,worm\n",
        csv_source);
    EXPECT_EQ(a.times, (std::vector<double>{0.5, 2.5}));
    ASSERT_EQ(a.structure.elements.size(), 2u);
    // Elements in the order the first frame's rows give them, samples by sample id.
    EXPECT_EQ(a.structure.types[a.structure.elements[0].type].name, "worm");
    EXPECT_EQ(a.at(0, 0), (Vec3{1, 1, 0}));
    EXPECT_EQ(a.at(0, 1), (Vec3{2, 1, 0}));
    EXPECT_EQ(a.at(1, 1), (Vec3{2, 2, 0}));
    EXPECT_EQ(a.at(1, 2), (Vec3{9, 9, 0}));
    // The bounding box of every frame.
    EXPECT_EQ(a.structure.domain.bounds().hi, (Vec3{9, 9, 0}));
}

TEST(IoAnimationCsv, FrameColumnWithoutTimeAndIdOnly) {
    const Animation a = parse_animation_csv(
        "frame,id,x,y\n"
        "3,7,1,1\n"
        "3,8,2,2\n"
        "1,8,4,4\n"
        "1,7,3,3\n",
        csv_source);
    EXPECT_EQ(a.times, (std::vector<double>{1, 3}));  // the frame numbers
    EXPECT_EQ(a.structure.elements[0].id, 8u);
    EXPECT_EQ(a.at(0, 0), (Vec3{4, 4, 0}));
    EXPECT_EQ(a.at(1, 0), (Vec3{2, 2, 0}));
    EXPECT_EQ(a.at(1, 1), (Vec3{1, 1, 0}));
}

TEST(IoAnimationCsv, LoadAndParseCsvGiveFrameZero) {
    const Animation a = test_animation(2);
    const Exemplar frame0 = parse_csv(animation_to_csv(a), "anim.csv", domain_of(a));
    ASSERT_EQ(frame0.samples.size(), static_cast<size_t>(a.sample_count()));
    for (int s = 0; s < a.sample_count(); ++s) EXPECT_EQ(frame0.samples[s].p, a.at(0, s));
}

TEST(IoAnimationCsv, RejectsDifferentElementSets) {
    const std::string header = "frame,element,sample,x,y\n";
    expect_csv_error(
        header + "0,a,0,1,1\n0,b,0,2,2\n1,a,0,1,1\n",
        "dir/anim.csv: frame 1: element 'b' is missing (every frame must hold the same elements)");
    expect_csv_error(header + "0,a,0,1,1\n1,a,0,1,1\n1,c,0,2,2\n",
                     "dir/anim.csv:4: frame 1: element 'c' is not in frame 0");
    expect_csv_error(header + "0,a,0,1,1\n0,a,1,1,2\n1,a,0,1,1\n1,a,2,1,2\n",
                     "dir/anim.csv:5: frame 1: element 'a' has sample 2, frame 0 has not");
    expect_csv_error("frame,id,x,y\n0,1,1,1\n0,2,2,2\n1,1,1,1\n1,1,2,2\n",
                     "dir/anim.csv:5: frame 1: element '1' appears twice (also on line 4)");
}

TEST(IoAnimationCsv, RejectsAThreadWithAMissingSampleId) {
    expect_csv_error(
        "frame,element,sample,x,y\n0,a,0,1,1\n0,a,1,1,2\n0,a,3,1,3\n1,a,0,1,1\n1,a,1,1,2\n1,a,3,1,3\n",
        "dir/anim.csv:4: frame 0: element 'a' has sample 3 but no sample 2");
}

TEST(IoAnimationCsv, RejectsTimeStampsThatDoNotIncrease) {
    expect_csv_error("frame,time,id,x,y\n0,1,1,1,1\n1,0.5,1,2,2\n",
                     "dir/anim.csv:3: frame 1: time stamps must strictly increase");
    expect_csv_error("frame,time,id,x,y\n0,0,1,1,1\n0,0.5,2,2,2\n",
                     "dir/anim.csv:3: frame 0 has time 0.5 here but 0 on line 2 (one time stamp per frame)");
}

TEST(IoAnimationCsv, RejectsElementsThatChangeAcrossFrames) {
    expect_csv_error("frame,id,x,y,class\n0,1,1,1,dot\n1,1,2,2,rock\n",
                     "dir/anim.csv:3: element '1' has a different class than on line 2");
    expect_csv_error("frame,element,x,y,hue\n0,a,1,1,0.5\n1,a,2,2,0.25\n",
                     "dir/anim.csv:3: element 'a' has a different attribute value than on line 2");
}

TEST(IoAnimationCsv, RejectsBadColumns) {
    expect_csv_error("frame,x,y\n0,1,1\n", "dir/anim.csv:1: a CSV with frames needs an element or id column");
    expect_csv_error("frame,t,id,x,y\n0,0,1,1,1\n",
                     "dir/anim.csv:1: columns frame and t cannot both be given");
    expect_csv_error("t,time,id,x,y\n0,0,1,1,1\n", "dir/anim.csv:1: columns t and time cannot both be given");
    expect_csv_error("frame,id,x,y\n0.5,1,1,1\n", "dir/anim.csv:2: frame is not an integer: '0.5'");
}

TEST(IoAnimationCsv, WriterRejectsAttributesNamedLikeTheNewColumns) {
    Animation a = test_animation(2);
    a.structure.attribute_names = {"t"};
    EXPECT_THROW(animation_to_csv(a), Error);
    EXPECT_THROW(to_csv(a.frame(0)), Error);
}

namespace {

class IoAnimationFiles : public tessera::test::TempDirTest {};

}  // namespace

TEST_F(IoAnimationFiles, SaveAndLoadJsonAndCsv) {
    const Animation a = test_animation(2);
    save_animation(a, path("a.json"));
    expect_same_animation(a, load_animation(path("a.json")), true);
    save_animation(a, path("a.CSV"));
    expect_same_animation(a, load_animation(path("a.CSV"), domain_of(a)), false, true);
    // load() gives frame 0 of either.
    EXPECT_EQ(load(path("a.json")).samples.back().p, a.at(0, a.sample_count() - 1));
    EXPECT_EQ(load(path("a.CSV"), domain_of(a)).samples.back().p, a.at(0, a.sample_count() - 1));
}

TEST_F(IoAnimationFiles, SaveWithStatsAndMeshPathsRelativeToTheFile) {
    Animation a = test_animation(2);
    a.structure.types[0].mesh = path("meshes/dot.obj");
    RunStats stats;
    stats.method = "dynamic";
    save_animation(a, stats, path("a.json"));
    const std::string text = read("a.json");
    EXPECT_NE(text.find(R"("mesh":"meshes/dot.obj")"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("stats": {"method":"dynamic")"), std::string::npos) << text;
    EXPECT_EQ(load_animation(path("a.json")).structure.types[0].mesh, path("meshes/dot.obj"));
}

TEST_F(IoAnimationFiles, StaticFilesAreOneFrame) {
    Exemplar ex = test_animation(2).frame(0);
    save(ex, path("s.json"));
    save(ex, path("s.csv"));
    for (const char* name : {"s.json", "s.csv"}) {
        const Animation a = load_animation(path(name));
        ASSERT_EQ(a.frame_count(), 1) << name;
        EXPECT_EQ(a.times, (std::vector<double>{0}));
        ASSERT_EQ(a.sample_count(), static_cast<int>(ex.samples.size()));
        for (int s = 0; s < a.sample_count(); ++s) EXPECT_EQ(a.at(0, s), ex.samples[s].p);
    }
}

TEST_F(IoAnimationFiles, HasFrames) {
    const Animation a = test_animation(2);
    save_animation(a, path("a.json"));
    save_animation(a, path("a.csv"));
    save(a.frame(0), path("s.json"));
    save(a.frame(0), path("s.csv"));
    write("t.csv", "\xEF\xBB\xBF# comment\n\n x , y , \"T\" ,id\n1,1,0,1\n");
    write("nested.json", R"({"format": "tessera", "stats": {"frames": []}, "elements": [{"frames": 1}]})");
    write("broken.json", R"({"format": "tess)");
    EXPECT_TRUE(has_frames(path("a.json")));
    EXPECT_TRUE(has_frames(path("a.csv")));
    EXPECT_TRUE(has_frames(path("t.csv")));
    EXPECT_FALSE(has_frames(path("s.json")));
    EXPECT_FALSE(has_frames(path("s.csv")));
    EXPECT_FALSE(has_frames(path("nested.json")));
    EXPECT_FALSE(has_frames(path("broken.json")));
    EXPECT_FALSE(has_frames(path("missing.json")));
    EXPECT_FALSE(has_frames(path("a.ply")));
}

TEST_F(IoAnimationFiles, ErrorsForExtensionsAndMissingFiles) {
    const Animation a = test_animation(2);
    try {
        save_animation(a, path("a.png"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("a.png: unsupported extension '.png' (supported: .json, .csv, .usda, .gltf, .glb)"),
                  std::string::npos)
            << e.what();
    }
    try {
        load_animation(path("missing.json"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::io);
    }
    EXPECT_THROW(load_animation(path("a.txt")), Error);
}
