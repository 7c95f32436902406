// Distribution editing (section 6.3) on a constructed case.
#include <gtest/gtest.h>

#include <set>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

// A square lattice (spacing 1) in a 20 x 20 box whose every third row is of type
// "b" and the others of type "a": interior "b" elements all share one neighbourhood,
// distinct from every "a" element's and from elements cut by the boundary.
Exemplar striped_lattice() {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {20, 20, 0}, 2);
    const int a = ex.type_index("a");
    const int b = ex.type_index("b");
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) ex.add_element(j % 3 == 1 ? b : a, {{i + 0.5, j + 0.5, 0}}, 0.3);
    return ex;
}

}  // namespace

TEST(DetEdit, PropagatesToSimilarNeighbourhoodsAndNoOthers) {
    const Exemplar ex = striped_lattice();
    ElementEdit edit;
    edit.element = 10 * 20 + 10;  // row 10 (type b), column 10: deep inside
    ASSERT_EQ(ex.types[ex.elements[edit.element].type].name, "b");
    edit.offset = {0.2, 0.1, 0};
    edit.radius = 0.45;
    EditReport report;
    EditOptions options;
    options.threshold = 0.5;  // below the cost of one missing neighbour (the cap, one spacing squared)
    const Exemplar out = edit_elements(ex, edit, options, &report);
    // Expected: the "b" elements whose whole neighbourhood (radius 2) lies inside.
    const double r = default_radius(ex);
    std::set<std::uint64_t> expected;
    for (const auto& e : ex.elements)
        if (ex.types[e.type].name == "b" && ex.domain.distance_to_boundary(e.position) > r) expected.insert(e.id);
    const std::set<std::uint64_t> changed(report.changed.begin(), report.changed.end());
    EXPECT_EQ(changed, expected);
    EXPECT_GT(expected.size(), 30u);
    // The automatic threshold also accepts neighbourhoods missing about one neighbour
    // (cut by the boundary), and still no "a" element.
    EditReport loose;
    edit_elements(ex, edit, EditOptions{}, &loose);
    EXPECT_GT(loose.changed.size(), expected.size());
    for (auto id : loose.changed) EXPECT_EQ(ex.types[ex.elements[id].type].name, "b");
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        const bool is_changed = changed.count(ex.elements[i].id) > 0;
        const Vec3 moved = out.elements[i].position - ex.elements[i].position;
        EXPECT_NEAR(norm(moved - (is_changed ? edit.offset : Vec3{})), 0.0, 1e-12);
        EXPECT_DOUBLE_EQ(out.elements[i].radius, is_changed ? 0.45 : 0.3);
    }
}

TEST(DetEdit, ReportsEditsOfThingsThatDoNotExist) {
    const Exemplar ex = striped_lattice();
    ElementEdit edit;
    edit.element = 4000;
    EXPECT_THROW(edit_elements(ex, edit), Error);
    edit.element = 3;
    edit.type = "c";
    EXPECT_THROW(edit_elements(ex, edit), Error);
    edit.type.reset();
    edit.attributes["hue"] = 1.0;
    EXPECT_THROW(edit_elements(ex, edit), Error);
    EXPECT_THROW(parse_edit_json(R"({"element": 1, "ofset": [1, 0]})", "e.json"), Error);
    EXPECT_THROW(parse_edit_json(R"({"offset": [1, 0]})", "e.json"), Error);
    const ElementEdit parsed = parse_edit_json(R"({"element": 7, "offset": [1, 2], "radius": 0.5})", "e.json");
    EXPECT_EQ(parsed.element, 7u);
    EXPECT_EQ(parsed.offset, Vec3(1, 2, 0));
    EXPECT_DOUBLE_EQ(*parsed.radius, 0.5);
}

TEST(DetEdit, LeavesLockedElementsAloneAndRefusesToEditOne) {
    Exemplar ex = striped_lattice();
    ElementEdit edit;
    edit.element = 10 * 20 + 10;
    edit.offset = {0.2, 0.1, 0};
    EditOptions options;
    options.threshold = 0.5;
    EditReport all;
    edit_elements(ex, edit, options, &all);
    ASSERT_GT(all.changed.size(), 10u);
    // Lock the half of the would-be changed elements with the smaller ids.
    std::set<std::uint64_t> locked;
    for (size_t k = 0; k < all.changed.size(); ++k)
        if (all.changed[k] != edit.element && k % 2 == 0) locked.insert(all.changed[k]);
    for (Element& e : ex.elements) e.locked = locked.count(e.id) > 0;
    EditReport report;
    const Exemplar out = edit_elements(ex, edit, options, &report);
    for (std::uint64_t id : report.changed) EXPECT_EQ(locked.count(id), 0u) << "locked element " << id << " edited";
    EXPECT_EQ(report.changed.size(), all.changed.size() - locked.size());
    for (size_t i = 0; i < ex.elements.size(); ++i)
        if (ex.elements[i].locked) {
            EXPECT_EQ(norm(out.elements[i].position - ex.elements[i].position), 0.0);
        }
    edit.element = *locked.begin();
    try {
        edit_elements(ex, edit, options);
        FAIL() << "a locked element was edited";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("locked"), std::string::npos) << e.what();
    }
}
