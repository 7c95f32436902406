// io/animation_files.cpp — the file-system side of animations (tessera/animation_io.hpp):
// load_animation and save_animation by extension, as load() and save() do for exemplars
// (same extension rules, mesh paths relative to the JSON file, atomic writes), and
// has_frames, the cheap look at a file the CLI uses to pick the dynamic method.
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "geometry/animated_scene.hpp"
#include "io/io_util.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"

namespace tessera {

using namespace io_detail;

namespace {

using Json = nlohmann::json;

// An animation writer: writes `data` (and `stats`, where the format has a place for them).
using AnimationWriter = void (*)(const Animation& data, const RunStats* stats, const std::string& path,
                                 const SaveOptions& options);

void write_json(const Animation& data, const RunStats* stats, const std::string& path, const SaveOptions&) {
    write_file_atomic(path, animation_to_json_with_mesh_paths(data, stats, [&](const std::string& mesh) {
                          return mesh_path_from(path, mesh);
                      }));
}

void write_csv(const Animation& data, const RunStats*, const std::string& path, const SaveOptions&) {
    write_file_atomic(path, animation_to_csv(data));
}

// A scene format of the animation (geometry/animated_scene.hpp): `to_text` of its animated
// scene, with the file's name on errors about the data, written only once it is whole.
template <typename ToText>
void write_scene_file(const Animation& data, const std::string& path, const SaveOptions& options, ToText to_text) {
    std::string text;
    try {
        text = to_text(geometry::build_animated_scene(data, options.geometry));
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::input) throw;
        throw Error(e.kind(), "cannot save animation " + path + ": " + e.what());
    }
    write_file_atomic(path, text);
}

// USD: instancer poses, curve and mesh points as time samples (docs/format.md, "USD").
void write_usda(const Animation& data, const RunStats*, const std::string& path, const SaveOptions& options) {
    write_scene_file(data, path, options, [](const auto& scene) { return geometry::to_usda_animated(scene); });
}

// glTF: node translations and rotations, morph target weights as animation channels.
void write_gltf(const Animation& data, const RunStats*, const std::string& path, const SaveOptions& options) {
    write_scene_file(data, path, options, [](const auto& scene) { return geometry::to_gltf_animated(scene, false); });
}

void write_glb(const Animation& data, const RunStats*, const std::string& path, const SaveOptions& options) {
    write_scene_file(data, path, options, [](const auto& scene) { return geometry::to_gltf_animated(scene, true); });
}

// The formats save_animation writes, by extension (lower case): one line per format.
struct AnimationFormat {
    const char* extension;
    AnimationWriter write;
};
constexpr AnimationFormat animation_formats[] = {
    {".json", write_json},
    {".csv", write_csv},
    {".usda", write_usda},
    {".gltf", write_gltf},
    {".glb", write_glb},
};

void save_by_extension(const Animation& data, const RunStats* stats, const std::string& path,
                       const SaveOptions& options) {
    const std::string extension = extension_of(path);
    std::string supported;
    for (const AnimationFormat& format : animation_formats) {
        if (extension == format.extension) return format.write(data, stats, path, options);
        supported += std::string(supported.empty() ? "" : ", ") + format.extension;
    }
    throw Error(ErrorKind::option, "cannot save animation " + path + ": unsupported extension '" + extension +
                                       "' (supported: " + supported + ")");
}

// Looks through a JSON document for a top-level key "frames", building nothing and
// stopping there.
class FramesKeyFinder : public nlohmann::json_sax<Json> {
public:
    bool found = false;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return enter(); }
    bool end_object() override { return leave(); }
    bool start_array(std::size_t) override { return enter(); }
    bool end_array() override { return leave(); }
    bool key(string_t& name) override {
        found = depth_ == 1 && name == "frames";
        return !found;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;
    }

private:
    int depth_ = 0;

    bool enter() {
        ++depth_;
        return true;
    }
    bool leave() {
        --depth_;
        return true;
    }
};

bool json_has_frames(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    FramesKeyFinder finder;
    Json::sax_parse(in, &finder);
    return finder.found;
}

// The header is the first line that is neither blank nor a comment.
bool csv_has_frames(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    for (int line_number = 1; std::getline(in, line); ++line_number) {
        std::string_view content = line;
        if (line_number == 1 && content.substr(0, 3) == "\xEF\xBB\xBF") content.remove_prefix(3);
        const std::string_view trimmed = trim(content);
        if (trimmed.empty() || trimmed.front() == '#') continue;
        try {
            for (const std::string& column : split_csv_fields(content, path, line_number)) {
                const std::string name = lower(column);
                if (name == "frame" || name == "t") return true;
            }
        } catch (const Error&) {
            // An unreadable header: loading the file says why.
        }
        return false;
    }
    return false;
}

}  // namespace

Animation load_animation(const std::string& path, const LoadOptions& options) {
    const std::string extension = load_extension(path);
    const std::string text = read_file(path);
    if (extension == ".csv") return parse_animation_csv(text, path, options);
    Animation data = parse_animation_json(text, path);
    resolve_mesh_paths(data.structure, path);
    return data;
}

void save_animation(const Animation& data, const std::string& path, const SaveOptions& options) {
    save_by_extension(data, nullptr, path, options);
}

void save_animation(const Animation& data, const RunStats& stats, const std::string& path,
                    const SaveOptions& options) {
    save_by_extension(data, &stats, path, options);
}

bool has_frames(const std::string& path) {
    const std::string extension = extension_of(path);
    if (extension == ".json") return json_has_frames(path);
    if (extension == ".csv") return csv_has_frames(path);
    return false;
}

}  // namespace tessera
