// core/animation.cpp — the space-time data model (tessera/animation.hpp): frames of one
// element set, their checks, and sample velocities.
#include "tessera/animation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "tessera/error.hpp"

namespace tessera {

namespace {

[[noreturn]] void fail_input(const std::string& source, const std::string& what) {
    throw Error(ErrorKind::input, source + ": " + what);
}

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

const char* topology_name(ElementTopology t) {
    switch (t) {
        case ElementTopology::automatic: return "automatic";
        case ElementTopology::none: return "none";
        case ElementTopology::thread: return "thread";
        case ElementTopology::sheet: return "sheet";
    }
    return "?";
}

void check_sample_ids(const Exemplar& data, const Element& e, int index, const std::string& source) {
    for (int k = 0; k < e.sample_count; ++k)
        if (data.samples[e.first_sample + k].sample_id != k)
            fail_input(source, "element " + std::to_string(e.id) + " (index " + std::to_string(index) + ") of " +
                                   topology_name(effective_topology(data, e.type)) + " type '" +
                                   data.types[e.type].name + "' has sample ids that are not 0.." +
                                   std::to_string(e.sample_count - 1) + " in order (a sample is missing or repeated)");
}

}  // namespace

Exemplar Animation::frame(int f) const {
    Exemplar out = structure;
    for (int s = 0; s < sample_count(); ++s) {
        out.samples[s].p = at(f, s);
        out.samples[s].time = times[f];
    }
    for (Element& e : out.elements) {
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) c = c + out.samples[e.first_sample + k].p;
        e.position = c / static_cast<double>(e.sample_count);
    }
    return out;
}

void Animation::add_frame(double time, const std::vector<Vec3>& sample_positions) {
    if (static_cast<int>(sample_positions.size()) != sample_count())
        throw Error(ErrorKind::internal, "Animation::add_frame: " + std::to_string(sample_positions.size()) +
                                             " positions for " + std::to_string(sample_count()) + " samples");
    times.push_back(time);
    positions.insert(positions.end(), sample_positions.begin(), sample_positions.end());
}

void Animation::validate(const std::string& source) const {
    structure.validate(source);
    if (times.empty()) fail_input(source, "the animation has no frame");
    if (positions.size() != times.size() * structure.samples.size())
        fail_input(source, "the animation holds " + std::to_string(positions.size()) + " sample positions for " +
                               std::to_string(times.size()) + " frames of " +
                               std::to_string(structure.samples.size()) + " samples");
    for (size_t f = 0; f < times.size(); ++f) {
        if (!std::isfinite(times[f])) fail_input(source, "frame " + std::to_string(f) + ": time is NaN or infinite");
        if (f > 0 && !(times[f] > times[f - 1]))
            fail_input(source, "frame " + std::to_string(f) + ": time stamps must strictly increase (" +
                                   std::to_string(times[f - 1]) + " then " + std::to_string(times[f]) + ")");
    }
    for (size_t i = 0; i < positions.size(); ++i)
        if (!finite(positions[i]))
            fail_input(source, "frame " + std::to_string(i / structure.samples.size()) +
                                   ": a coordinate is NaN or infinite");
    check_topology(structure, source);
}

Animation animation_from_exemplar(const Exemplar& exemplar, double time) {
    Animation a;
    a.structure = exemplar;
    std::vector<Vec3> p(exemplar.samples.size());
    for (size_t s = 0; s < p.size(); ++s) p[s] = exemplar.samples[s].p;
    a.add_frame(time, p);
    for (Sample& s : a.structure.samples) s.time = time;
    return a;
}

Animation animation_from_frames(const std::vector<Exemplar>& frames, const std::vector<double>& times,
                                const std::string& source) {
    if (frames.empty()) fail_input(source, "the animation has no frame");
    if (times.size() != frames.size())
        throw Error(ErrorKind::internal, "animation_from_frames: " + std::to_string(times.size()) +
                                             " times for " + std::to_string(frames.size()) + " frames");
    Animation a;
    a.structure = frames[0];
    std::map<std::uint64_t, int> index_of_id;
    for (size_t e = 0; e < a.structure.elements.size(); ++e) {
        if (!index_of_id.emplace(a.structure.elements[e].id, static_cast<int>(e)).second)
            fail_input(source, "frame 0: element id " + std::to_string(a.structure.elements[e].id) + " appears twice");
    }
    for (size_t f = 0; f < frames.size(); ++f) {
        const Exemplar& fr = frames[f];
        const std::string where = "frame " + std::to_string(f);
        if (f > 0 && !(times[f] > times[f - 1]))
            fail_input(source, where + ": time stamps must strictly increase (" + std::to_string(times[f - 1]) +
                                   " then " + std::to_string(times[f]) + ")");
        if (fr.elements.size() != a.structure.elements.size())
            fail_input(source, where + " has " + std::to_string(fr.elements.size()) + " elements, frame 0 has " +
                                   std::to_string(a.structure.elements.size()) +
                                   " (every frame must hold the same elements)");
        std::vector<Vec3> p(a.structure.samples.size());
        std::vector<char> seen(a.structure.elements.size(), 0);
        for (const Element& e : fr.elements) {
            const auto it = index_of_id.find(e.id);
            if (it == index_of_id.end())
                fail_input(source, where + ": element id " + std::to_string(e.id) +
                                       " is not in frame 0 (every frame must hold the same elements)");
            if (seen[it->second]++)
                fail_input(source, where + ": element id " + std::to_string(e.id) + " appears twice");
            const Element& base = a.structure.elements[it->second];
            if (fr.types[e.type].name != a.structure.types[base.type].name || e.sample_count != base.sample_count)
                fail_input(source, where + ": element id " + std::to_string(e.id) +
                                       " has another type or sample count than in frame 0");
            for (int k = 0; k < e.sample_count; ++k) p[base.first_sample + k] = fr.samples[e.first_sample + k].p;
        }
        a.add_frame(times[f], p);
    }
    for (Sample& s : a.structure.samples) s.time = times[0];
    a.validate(source);
    return a;
}

ElementTopology effective_topology(const Exemplar& data, int type) {
    const ElementTopology t = data.types[type].topology;
    if (t != ElementTopology::automatic) return t;
    for (const Element& e : data.elements)
        if (e.type == type) return e.sample_count > 1 ? ElementTopology::thread : ElementTopology::none;
    return ElementTopology::none;
}

void check_topology(const Exemplar& data, const std::string& source) {
    for (size_t t = 0; t < data.types.size(); ++t) {
        const ElementType& type = data.types[t];
        const ElementTopology topo = effective_topology(data, static_cast<int>(t));
        if (topo != ElementTopology::sheet && type.sheet_columns != 0)
            fail_input(source, "type '" + type.name + "': columns are given but its topology is " +
                                   topology_name(topo) + ", not sheet");
        for (size_t e = 0; e < data.elements.size(); ++e) {
            const Element& el = data.elements[e];
            if (el.type != static_cast<int>(t)) continue;
            if (topo == ElementTopology::thread && el.sample_count < 2)
                fail_input(source, "type '" + type.name + "' is a thread but its elements have " +
                                       std::to_string(el.sample_count) + " sample (a thread needs 2 or more)");
            if (topo == ElementTopology::sheet) {
                const int c = type.sheet_columns;
                if (c < 2 || el.sample_count % c != 0 || el.sample_count / c < 2)
                    fail_input(source, "type '" + type.name + "' is a sheet but its " +
                                           std::to_string(el.sample_count) + " samples are not a grid of " +
                                           std::to_string(c) + " columns and 2 or more rows");
            }
            if (topo == ElementTopology::thread || topo == ElementTopology::sheet)
                check_sample_ids(data, el, static_cast<int>(e), source);
        }
    }
}

std::vector<Vec3> sample_velocities(const Animation& animation) {
    const int n = animation.sample_count(), frames = animation.frame_count();
    std::vector<Vec3> v(animation.positions.size());
    for (int f = 1; f < frames; ++f) {
        const double dt = animation.times[f] - animation.times[f - 1];
        for (int s = 0; s < n; ++s) v[static_cast<size_t>(f) * n + s] = (animation.at(f, s) - animation.at(f - 1, s)) / dt;
    }
    if (frames > 1)
        std::copy(v.begin() + n, v.begin() + 2 * n, v.begin());
    return v;
}

}  // namespace tessera
