// Exemplar helpers: building elements and checking the data model's invariants.
#include "tessera/exemplar.hpp"

#include <cmath>
#include <sstream>
#include <unordered_set>

#include "tessera/error.hpp"

namespace tessera {

namespace {

// Brushing's per-type fields (brush.hpp): a weight > 0 per sample id, graph edges between
// two distinct sample ids of the type's elements. `count` is the type's sample count (-1
// when the type has no element).
template <class Fail>
void validate_brush_fields(const ElementType& type, int count, const Fail& fail) {
    const std::string which = "element type '" + type.name + "'";
    for (double w : type.weights)
        if (!std::isfinite(w) || !(w > 0.0)) fail(which + " has a sample weight that is not a number > 0");
    if (!type.weights.empty() && count >= 0 && count != static_cast<int>(type.weights.size()))
        fail(which + " has " + std::to_string(type.weights.size()) + " sample weights but its elements have " +
             std::to_string(count) + " samples");
    for (const auto& edge : type.graph) {
        const bool in_range = count < 0 || (edge[0] < count && edge[1] < count);
        if (edge[0] < 0 || edge[1] < 0 || edge[0] == edge[1] || !in_range)
            fail(which + " has a graph edge [" + std::to_string(edge[0]) + ", " + std::to_string(edge[1]) +
                 "] that does not join two of its " + std::to_string(count) + " samples");
    }
}

}  // namespace

int Exemplar::find_type(const std::string& name) const {
    for (size_t i = 0; i < types.size(); ++i)
        if (types[i].name == name) return static_cast<int>(i);
    return -1;
}

int Exemplar::type_index(const std::string& name) {
    const int found = find_type(name);
    if (found >= 0) return found;
    ElementType t;
    t.name = name;
    types.push_back(std::move(t));
    return static_cast<int>(types.size()) - 1;
}

int Exemplar::add_element(int type, const std::vector<Vec3>& positions, double radius) {
    Element e;
    e.type = type;
    e.first_sample = static_cast<int>(samples.size());
    e.sample_count = static_cast<int>(positions.size());
    e.radius = radius;
    const int index = static_cast<int>(elements.size());
    e.id = static_cast<std::uint64_t>(index);
    Vec3 c;
    for (size_t s = 0; s < positions.size(); ++s) {
        samples.push_back(Sample{positions[s], index, static_cast<int>(s), 0.0});
        c += positions[s];
    }
    if (!positions.empty()) e.position = c / static_cast<double>(positions.size());
    elements.push_back(std::move(e));
    return index;
}

void Exemplar::update_positions() {
    for (auto& e : elements) {
        if (e.locked) continue;  // a locked element's pose is the user's, to the bit
        Vec3 c;
        for (int s = 0; s < e.sample_count; ++s) c += samples[e.first_sample + s].p;
        if (e.sample_count > 0) e.position = c / static_cast<double>(e.sample_count);
    }
}

bool Exemplar::has_multi_sample_elements() const {
    for (const auto& e : elements)
        if (e.sample_count > 1) return true;
    return false;
}

void Exemplar::validate(const std::string& source) const {
    auto fail = [&](const std::string& what) { throw Error(ErrorKind::input, source + ": " + what); };
    if (dimension != 2 && dimension != 3) fail("dimension must be 2 or 3");
    if (elements.empty()) fail("no elements (the exemplar is empty)");
    if (types.empty()) fail("no element types");
    if (domain.dimension() != dimension) fail("domain dimension differs from the data's dimension");
    std::unordered_set<std::string> names;
    for (const auto& t : types) {
        if (t.name.empty()) fail("an element type has an empty name");
        if (!names.insert(t.name).second) fail("element type '" + t.name + "' is defined twice");
    }
    std::vector<int> count_of_type(types.size(), -1);
    int expected_first = 0;
    for (size_t i = 0; i < elements.size(); ++i) {
        const auto& e = elements[i];
        const std::string which = "element " + std::to_string(i);
        if (e.type < 0 || e.type >= static_cast<int>(types.size())) fail(which + " has an unknown element type");
        if (e.sample_count < 1) fail(which + " has no samples");
        if (e.first_sample != expected_first) fail(which + " does not own a contiguous run of samples");
        expected_first += e.sample_count;
        if (!(e.radius >= 0.0) || !std::isfinite(e.radius)) fail(which + " has a radius that is negative or not finite");
        if (!std::isfinite(e.scale) || !(e.scale > 0.0)) fail(which + " has a scale that is not > 0");
        if (e.attributes.size() != attribute_names.size())
            fail(which + " has " + std::to_string(e.attributes.size()) + " attributes, expected " +
                 std::to_string(attribute_names.size()));
        for (double a : e.attributes)
            if (!std::isfinite(a)) fail(which + " has an attribute that is not finite");
        int& c = count_of_type[e.type];
        if (c < 0) c = e.sample_count;
        else if (c != e.sample_count)
            fail("elements of type '" + types[e.type].name + "' have different sample counts (" +
                 std::to_string(c) + " and " + std::to_string(e.sample_count) + ")");
    }
    if (expected_first != static_cast<int>(samples.size())) fail("samples do not match the elements' sample runs");
    // A reference layout (geometry.hpp) places each of the type's samples in the mesh's frame.
    for (size_t t = 0; t < types.size(); ++t) {
        const auto& reference = types[t].reference;
        for (const Vec3& r : reference)
            if (!is_finite(r)) fail("element type '" + types[t].name + "' has a reference point that is NaN or infinite");
        if (!reference.empty() && count_of_type[t] >= 0 && count_of_type[t] != static_cast<int>(reference.size()))
            fail("element type '" + types[t].name + "' has a reference layout of " + std::to_string(reference.size()) +
                 " samples but its elements have " + std::to_string(count_of_type[t]));
        validate_brush_fields(types[t], count_of_type[t], fail);
    }
    for (size_t i = 0; i < samples.size(); ++i) {
        const auto& s = samples[i];
        if (!is_finite(s.p)) fail("sample " + std::to_string(i) + " has a coordinate that is NaN or infinite");
        if (s.element < 0 || s.element >= static_cast<int>(elements.size()))
            fail("sample " + std::to_string(i) + " names an element that does not exist");
        const auto& e = elements[s.element];
        if (static_cast<int>(i) < e.first_sample || static_cast<int>(i) >= e.first_sample + e.sample_count)
            fail("sample " + std::to_string(i) + " names the wrong element");
        if (s.sample_id != static_cast<int>(i) - e.first_sample)
            fail("sample " + std::to_string(i) + " has sample id out of order");
    }
}

}  // namespace tessera
