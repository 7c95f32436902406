// Distribution editing (section 6.3): propagate one element's edit to the elements
// whose neighbourhoods are similar to its own, with the metric of Eq. 1.
#include "tessera/edit.hpp"

#include <cmath>

#include "core/parallel.hpp"
#include "det/input_index.hpp"
#include "det/matching.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

int find_element(const Exemplar& data, std::uint64_t id) {
    for (size_t i = 0; i < data.elements.size(); ++i)
        if (data.elements[i].id == id) return static_cast<int>(i);
    throw Error(ErrorKind::input, "the edit names element " + std::to_string(id) + ", which does not exist");
}

void check_edit(const Exemplar& data, const ElementEdit& edit) {
    if (!is_finite(edit.offset)) throw Error(ErrorKind::input, "the edit's offset must be finite");
    if (edit.type && data.find_type(*edit.type) < 0)
        throw Error(ErrorKind::input, "the edit names type '" + *edit.type + "', which does not exist");
    if (edit.radius && (!std::isfinite(*edit.radius) || !(*edit.radius > 0.0)))
        throw Error(ErrorKind::input, "the edit's radius must be > 0");
    if (edit.angle && !std::isfinite(*edit.angle)) throw Error(ErrorKind::input, "the edit's angle must be finite");
    for (const auto& [name, value] : edit.attributes) {
        bool known = false;
        for (const auto& a : data.attribute_names) known = known || a == name;
        if (!known) throw Error(ErrorKind::input, "the edit names attribute '" + name + "', which does not exist");
        if (!std::isfinite(value)) throw Error(ErrorKind::input, "the edit's attribute '" + name + "' must be finite");
    }
}

// A sample's neighbourhood within r, from the index's wider neighbourhood (key-sorted).
void neighbourhood_within(const det::InputIndex& index, int i, double r, std::vector<det::NeighborEntry>& out) {
    out.clear();
    for (int q = 0; q < index.neighbor_count(i); ++q)
        if (squared_norm(index.neighbors(i)[q].offset) <= r * r) out.push_back(index.neighbors(i)[q]);
}

void apply(Exemplar& data, int e, const ElementEdit& edit) {
    Element& el = data.elements[e];
    for (int s = 0; s < el.sample_count; ++s) data.samples[el.first_sample + s].p += edit.offset;
    el.position += edit.offset;
    if (edit.type) el.type = data.find_type(*edit.type);
    if (edit.radius) el.radius = *edit.radius;
    if (edit.angle) el.orientation = Quat::from_angle_z(*edit.angle);
    for (const auto& [name, value] : edit.attributes)
        for (size_t k = 0; k < data.attribute_names.size(); ++k)
            if (data.attribute_names[k] == name) el.attributes[k] = value;
}

}  // namespace

Exemplar edit_elements(const Exemplar& data, const ElementEdit& edit, const EditOptions& options,
                       EditReport* report) {
    data.validate("the data to edit");
    check_options(edit_option_table(), options);  // each field against its row, naming it
    check_edit(data, edit);
    const int edited = find_element(data, edit.element);
    if (data.elements[edited].locked)
        throw Error(ErrorKind::input, "the edit names element " + std::to_string(edit.element) + ", which is locked");
    DetOptions det_options;
    det_options.radius = options.radius;
    const det::Params params = det::resolve_params(data, det_options);
    const det::InputIndex index = det::build_input_index(data, params, 0, options.threads);

    // The edited element's sample neighbourhoods play the "output" side of Eq. 1.
    const Element& source = data.elements[edited];
    std::vector<std::vector<det::NeighborEntry>> own(source.sample_count);
    size_t neighbours = 0;
    for (int s = 0; s < source.sample_count; ++s) {
        neighbourhood_within(index, source.first_sample + s, params.radius, own[s]);
        neighbours += own[s].size();
    }
    const double threshold =
        options.threshold >= 0.0 ? options.threshold : 0.1 * params.spacing * params.spacing * std::max<size_t>(1, neighbours);

    // Distance of every element of the same type and sample count to the edited one.
    const int n = static_cast<int>(data.elements.size());
    std::vector<double> distance(n, INFINITY);
    const int threads = core::resolve_threads(options.threads);
    std::vector<det::MatchScratch> scratch(threads);
    core::parallel_for(n, threads, [&](int begin, int end, int t) {
        for (int e = begin; e < end; ++e) {
            const Element& el = data.elements[e];
            if (el.locked || el.sample_count != source.sample_count) continue;  // locked: never changed
            if (el.sample_count > 1 && el.type != source.type) continue;
            double d = 0.0;
            for (int s = 0; s < el.sample_count && d <= threshold; ++s) {
                const int i = el.first_sample + s;
                d += det::match_neighborhoods(own[s].data(), static_cast<int>(own[s].size()), index.neighbors(i),
                                              index.neighbor_count(i), params, scratch[t], nullptr, INFINITY);
            }
            if (el.sample_count == 1 && el.type != source.type) d += params.alpha;  // centre term of Eq. 1
            distance[e] = d;
        }
    });

    Exemplar result = data;
    EditReport local;
    local.threshold = threshold;
    for (int e = 0; e < n; ++e) {
        if (e != edited && !(distance[e] <= threshold)) continue;
        apply(result, e, edit);
        local.changed.push_back(data.elements[e].id);
    }
    if (report) *report = std::move(local);
    return result;
}

}  // namespace tessera
