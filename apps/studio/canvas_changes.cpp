// apps/studio/canvas_changes.cpp — the elements an operation appended (canvas_changes.hpp).
#include "apps/studio/canvas_changes.hpp"

#include "tessera/io.hpp"

namespace tessera_studio {

CanvasMark mark_canvas(const tessera::BrushCanvas& canvas) {
    const tessera::Arrangement& a = canvas.arrangement();
    CanvasMark mark;
    mark.elements = a.elements.size();
    mark.positions.reserve(a.samples.size());
    for (const tessera::Sample& s : a.samples) mark.positions.push_back(s.p);
    mark.directions = canvas.sample_directions();
    return mark;
}

namespace {

// Whether the first elements and samples are those of `before`, bit for bit.
bool only_appended(const tessera::BrushCanvas& canvas, const CanvasMark& before) {
    const tessera::Arrangement& a = canvas.arrangement();
    const std::vector<tessera::Vec3>& directions = canvas.sample_directions();
    if (a.elements.size() < before.elements || a.samples.size() < before.positions.size() ||
        directions.size() < before.directions.size())
        return false;
    for (size_t s = 0; s < before.positions.size(); ++s)
        if (!(a.samples[s].p == before.positions[s])) return false;
    for (size_t s = 0; s < before.directions.size(); ++s)
        if (!(directions[s] == before.directions[s])) return false;
    return before.elements == 0 ||
           static_cast<size_t>(a.elements[before.elements - 1].first_sample +
                               a.elements[before.elements - 1].sample_count) == before.positions.size();
}

// The elements from `first` on, as an arrangement of their own (all types kept).
tessera::Arrangement tail_of(const tessera::Arrangement& a, size_t first) {
    tessera::Arrangement tail;
    tail.dimension = a.dimension;
    tail.types = a.types;
    tail.attribute_names = a.attribute_names;
    tail.domain = a.domain;
    for (size_t e = first; e < a.elements.size(); ++e) {
        tessera::Element element = a.elements[e];
        element.first_sample = static_cast<int>(tail.samples.size());
        for (int k = 0; k < element.sample_count; ++k) {
            tessera::Sample s = a.samples[a.elements[e].first_sample + k];
            s.element = static_cast<int>(tail.elements.size());
            tail.samples.push_back(s);
        }
        tail.elements.push_back(std::move(element));
    }
    return tail;
}

}  // namespace

Json appended_since(const tessera::BrushCanvas& canvas, const CanvasMark& before) {
    if (!only_appended(canvas, before)) return nullptr;
    const tessera::Arrangement& a = canvas.arrangement();
    const size_t first_sample = before.positions.size();
    Json directions = Json::array();
    const std::vector<tessera::Vec3>& all = canvas.sample_directions();
    for (size_t s = first_sample; s < all.size(); ++s) directions.push_back({all[s].x, all[s].y, all[s].z});
    const std::vector<int> entries = canvas.sample_exemplars();
    return {{"first_element", before.elements},
            {"first_sample", first_sample},
            {"arrangement", Json::parse(tessera::to_json(tail_of(a, before.elements)))},
            {"directions", std::move(directions)},
            {"exemplars", std::vector<int>(entries.begin() + static_cast<long>(first_sample), entries.end())}};
}

}  // namespace tessera_studio
