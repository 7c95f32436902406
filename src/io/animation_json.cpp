// io/animation_json.cpp — animations in the native JSON format (docs/format.md,
// "Animations (frames)"): the ordinary document, whose "elements" define the elements
// (type, id, radius, pose, attributes, lock) without positions, plus a top-level "frames"
// array; each frame is {"time": T, "elements": [...]} and gives every element's "position"
// or "samples" by id.
//
// The frames are read and checked here: every frame holds the same ids with the same
// sample counts and keys, and the time stamps strictly increase. The rest of the document
// goes through the static reader (json_format.cpp), which takes each element's samples
// from frame 0, so that both kinds of file are read by the same rules. The writer writes
// the definitions and every frame element one per line, through the static writer's pieces.
#include <algorithm>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "io/io_util.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"

namespace tessera {

using namespace io_detail;

namespace {

using Json = nlohmann::json;

// The "frames" of an animated document, read and checked against frames[0]. Elements are
// kept by slot: their index in frames[0].
class FramesReader {
public:
    FramesReader(const std::string& source, int dimension) : source_(source), dimension_(dimension) {}

    void read(const Json& frames) {
        json_array(frames, source_, "frames");
        if (frames.empty()) fail("frames", "must hold at least one frame");
        for (size_t f = 0; f < frames.size(); ++f) read_frame(frames[f], f);
        defined_.assign(ids_.size(), false);
    }

    // Frame 0's samples of the element `id`, defined at `where` in "elements".
    std::vector<Vec3> first_samples(std::uint64_t id, const std::string& where) {
        const auto it = slot_of_.find(id);
        if (it == slot_of_.end())
            fail(where, "element id " + std::to_string(id) +
                            " is in no frame (every frame must hold every element)");
        defined_[it->second] = true;
        return points_.front()[it->second];
    }

    // After the definitions are read: every element of the frames must have one.
    void check_all_defined() const {
        for (size_t k = 0; k < defined_.size(); ++k)
            if (!defined_[k])
                fail("frames[0].elements[" + std::to_string(k) + "]",
                     "element id " + std::to_string(ids_[k]) + " is not defined in \"elements\"");
    }

    // The animation of `structure` (read with first_samples) through all frames.
    Animation animation(Exemplar structure) const {
        Animation a;
        a.structure = std::move(structure);
        for (size_t f = 0; f < times_.size(); ++f) {
            std::vector<Vec3> p(a.structure.samples.size());
            for (const Element& e : a.structure.elements) {
                const std::vector<Vec3>& samples = points_[f][slot_of_.at(e.id)];
                std::copy(samples.begin(), samples.end(), p.begin() + e.first_sample);
            }
            a.add_frame(times_[f], p);
        }
        for (Sample& s : a.structure.samples) s.time = times_.front();
        return a;
    }

private:
    std::string source_;
    int dimension_;
    std::vector<double> times_;
    std::vector<std::vector<std::vector<Vec3>>> points_;  // [frame][slot] -> sample positions
    std::vector<std::uint64_t> ids_;                      // [slot]
    std::vector<bool> uses_samples_;                      // [slot]: "samples" rather than "position"
    std::map<std::uint64_t, size_t> slot_of_;             // id -> slot
    std::vector<bool> defined_;                           // [slot]: has a definition in "elements"

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        fail_input(source_, 0, where + ": " + what);
    }

    static std::string id_text(std::uint64_t id) { return "element id " + std::to_string(id); }

    void read_frame(const Json& frame, size_t f) {
        const std::string where = "frames[" + std::to_string(f) + "]";
        if (!frame.is_object())
            fail(where, "must be an object {\"time\": T, \"elements\": [...]}, got " + frame.dump());
        check_json_keys(frame, {"time", "elements"}, source_, where);
        const double time =
            json_number(json_require(frame, "time", source_, where), source_, where + ".time");
        if (f > 0 && !(time > times_.back()))
            fail(where + ".time", "time stamps must strictly increase (" + json_number_text(times_.back()) +
                                      " in frames[" + std::to_string(f - 1) + "], then " +
                                      json_number_text(time) + ")");
        times_.push_back(time);
        const std::string at = where + ".elements";
        const Json& elements = json_array(json_require(frame, "elements", source_, where), source_, at);
        points_.emplace_back(ids_.size());
        std::vector<bool> seen(ids_.size(), false);
        for (size_t k = 0; k < elements.size(); ++k) {
            const std::string element_at = at + "[" + std::to_string(k) + "]";
            if (f == 0)
                add_first(elements[k], element_at);
            else
                add_matched(elements[k], element_at, seen);
        }
        for (size_t k = 0; k < seen.size(); ++k)
            if (!seen[k])
                fail(where, id_text(ids_[k]) + " is missing (every frame must hold the same elements)");
    }

    // A frame element's id and samples; `uses_samples` tells which key gave them.
    std::pair<std::uint64_t, std::vector<Vec3>> element(const Json& e, const std::string& where,
                                                        bool& uses_samples) const {
        if (!e.is_object())
            fail(where, "must be an object {\"id\": ID, \"position\" or \"samples\": ...}, got " + e.dump());
        check_json_keys(e, {"id", "position", "samples"}, source_, where);
        const std::uint64_t id =
            json_element_id(json_require(e, "id", source_, where), source_, where + ".id");
        uses_samples = e.contains("samples");
        return {id, json_element_samples(e, dimension_, source_, where)};
    }

    // An element of frames[0]: gets the next slot.
    void add_first(const Json& e, const std::string& where) {
        bool uses_samples = false;
        auto [id, samples] = element(e, where, uses_samples);
        if (!slot_of_.emplace(id, ids_.size()).second)
            fail(where, id_text(id) + " appears twice in the frame");
        ids_.push_back(id);
        uses_samples_.push_back(uses_samples);
        points_.back().push_back(std::move(samples));
    }

    // An element of a later frame: must be frames[0]'s, with the same key and sample count.
    void add_matched(const Json& e, const std::string& where, std::vector<bool>& seen) {
        bool uses_samples = false;
        auto [id, samples] = element(e, where, uses_samples);
        const auto it = slot_of_.find(id);
        if (it == slot_of_.end())
            fail(where, id_text(id) + " is not in frames[0] (every frame must hold the same elements)");
        const size_t slot = it->second;
        if (seen[slot]) fail(where, id_text(id) + " appears twice in the frame");
        seen[slot] = true;
        const auto key = [](bool samples_key) { return samples_key ? "\"samples\"" : "\"position\""; };
        if (uses_samples != uses_samples_[slot])
            fail(where, id_text(id) + " has " + key(uses_samples) + " here but " + key(uses_samples_[slot]) +
                            " in frames[0] (an element must use the same key in every frame)");
        const size_t expected = points_.front()[slot].size();
        if (samples.size() != expected)
            fail(where, id_text(id) + " has " + std::to_string(samples.size()) + " samples here but " +
                            std::to_string(expected) +
                            " in frames[0] (every frame must hold the same samples)");
        points_.back()[slot] = std::move(samples);
    }
};

}  // namespace

Animation io_detail::read_json_animation(const Json& doc, const std::string& source) {
    FramesReader frames(source, json_document_dimension(doc, source));
    frames.read(doc.at("frames"));
    const JsonFrameSamples samples = [&](std::uint64_t id, const std::string& where) {
        return frames.first_samples(id, where);
    };
    Exemplar structure = read_json_document(doc, source, &samples);
    frames.check_all_defined();
    Animation animation = frames.animation(std::move(structure));
    animation.validate(source);
    return animation;
}

Animation parse_animation_json(const std::string& text, const std::string& source) {
    const Json doc = parse_json_text(text, source);
    if (doc.is_object() && doc.contains("frames")) return read_json_animation(doc, source);
    return animation_from_exemplar(read_json_document(doc, source));
}

std::string animation_to_json(const Animation& data, const RunStats* stats) {
    return animation_to_json_with_mesh_paths(data, stats, [](const std::string& mesh) { return mesh; });
}

std::string io_detail::animation_to_json_with_mesh_paths(const Animation& data, const RunStats* stats,
                                                         const MeshPath& mesh_path) {
    std::vector<std::string> definitions;
    definitions.reserve(data.structure.elements.size());
    for (const Element& e : data.structure.elements)
        definitions.push_back(json_element_line(data.structure, e, JsonElementPart::definition));
    std::string frames = ",\n  \"frames\": [\n";
    for (int f = 0; f < data.frame_count(); ++f) {
        const Exemplar frame = data.frame(f);
        frames += "    {\"time\": " + json_number_text(data.times[f]) + ", \"elements\": [\n";
        for (size_t i = 0; i < frame.elements.size(); ++i) {
            frames += "      " + json_element_line(frame, frame.elements[i], JsonElementPart::samples);
            frames += i + 1 < frame.elements.size() ? ",\n" : "\n";
        }
        frames += f + 1 < data.frame_count() ? "    ]},\n" : "    ]}\n";
    }
    frames += "  ]";
    return json_document(data.structure, definitions, frames, stats, mesh_path);
}

}  // namespace tessera
