// apps/tessera/common.cpp — the shared CLI vocabulary: common options, input
// loading with --input-domain, output path checks and exit codes.
#include "common.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "tessera/option_text.hpp"

namespace tessera_cli {

int exit_code(tessera::ErrorKind kind) {
    switch (kind) {
        case tessera::ErrorKind::input:
            return exit_input;
        case tessera::ErrorKind::domain:
            return exit_domain;
        case tessera::ErrorKind::option:
            return exit_option;
        case tessera::ErrorKind::io:
            return exit_io;
        case tessera::ErrorKind::internal:
            return exit_internal;
        case tessera::ErrorKind::cancelled:
            return exit_cancelled;
    }
    return exit_internal;
}

void print_error(const std::string& message) {
    // One line, whatever the message holds.
    std::string line = message;
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::cerr << "tessera: error: " << line << std::endl;
}

void fail_option(const std::string& message) {
    throw tessera::Error(tessera::ErrorKind::option, message);
}

std::optional<std::string> integer_digits(const std::string& text) {
    size_t at = 0;
    const bool negative = at < text.size() && text[at] == '-';
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
    // Mantissa: digits with an optional point; `point` = digits before the point.
    std::string digits;
    size_t point = std::string::npos;
    for (; at < text.size(); ++at) {
        const char c = text[at];
        if (c >= '0' && c <= '9') digits += c;
        else if (c == '.' && point == std::string::npos) point = digits.size();
        else break;
    }
    if (digits.empty()) return std::nullopt;
    if (point == std::string::npos) point = digits.size();
    // Exponent, bounded: past a few hundred it is out of range of every type anyway.
    long exponent = 0;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        const bool minus = at < text.size() && text[at] == '-';
        if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
        if (at == text.size()) return std::nullopt;
        for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at)
            exponent = std::min(exponent * 10 + (text[at] - '0'), 100000L);
        if (minus) exponent = -exponent;
    }
    if (at != text.size()) return std::nullopt;
    const size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return std::string("0");
    // Shift the point by the exponent; what stays behind it must be zeros.
    const long shifted = static_cast<long>(point) + exponent;
    if (shifted <= static_cast<long>(first)) return std::nullopt;  // below 1 and not 0
    if (shifted > 400) return std::string(negative ? "-" : "") + "1" + std::string(400, '0');  // surely out of range
    std::string whole = digits.substr(0, std::min<size_t>(digits.size(), static_cast<size_t>(shifted)));
    if (static_cast<size_t>(shifted) > digits.size()) whole += std::string(static_cast<size_t>(shifted) - digits.size(), '0');
    else if (digits.find_first_not_of('0', static_cast<size_t>(shifted)) != std::string::npos) return std::nullopt;
    whole.erase(0, whole.find_first_not_of('0'));
    return (negative ? "-" : "") + whole;
}

CLI::Validator integer_notation(long long lo, unsigned long long hi) {
    const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            const std::optional<std::string> digits = integer_digits(text);
            if (!digits) {
                char* end = nullptr;
                std::strtod(text.c_str(), &end);  // a number of another kind ("1.5", "inf")?
                const bool number = !text.empty() && end == text.c_str() + text.size();
                return text + (number ? " is not an integer" : " is not a number");
            }
            const bool negative = (*digits)[0] == '-';
            unsigned long long magnitude = 0;
            const char* begin = digits->data() + (negative ? 1 : 0);
            const auto parsed = std::from_chars(begin, digits->data() + digits->size(), magnitude);
            const unsigned long long lowest = lo < 0 ? 0ULL - static_cast<unsigned long long>(lo) : 0ULL;
            if (parsed.ec != std::errc() || (negative ? magnitude > lowest : magnitude > hi))
                return text + " is out of range (" + range + ")";
            text = *digits;
            return "";
        },
        "");
}

void rethrow_with_flag_names(const tessera::Error& e, FlagNames names) {
    const std::string message = e.what();
    if (e.kind() == tessera::ErrorKind::option)
        for (const auto& [field, flag] : names) {
            const std::string prefix = std::string(field) + ": ";
            if (message.rfind(prefix, 0) == 0)
                throw tessera::Error(e.kind(), std::string(flag) + ": " + message.substr(prefix.size()));
        }
    throw;
}

void check_meshes_for_picture(tessera::RenderOptions::Meshes meshes, const std::string& path) {
    if (meshes == tessera::RenderOptions::Meshes::on && extension_of(path) != ".png")
        fail_option("--meshes on: element meshes are drawn in .png pictures only, not in " + path +
                    " (use a .png, or --meshes auto|off)");
}

CLI::Option* add_output_option(CLI::App& app, std::string& path, const std::string& what, bool required) {
    CLI::Option* option = app.add_option("-o,--output", path, what);
    if (required) option->required();
    return option->type_name("FILE");
}

CLI::Option* add_input_domain_option(CLI::App& app, std::string& text, const std::string& operand) {
    return app
        .add_option("--input-domain", text,
                    "Observation window of " + operand +
                        ", xmin,ymin,xmax,ymax (2D) or "
                        "xmin,ymin,xmax,ymax,zmin,zmax (3D). For a CSV input it is the domain the "
                        "points were observed in (default: their bounding box); for a JSON input it "
                        "replaces the domain stored in the file (default: the file's domain).")
        ->type_name("BOX");
}

CLI::Option* add_quiet_option(CLI::App& app, bool& quiet) {
    return app.add_flag("-q,--quiet", quiet, "Print nothing to stderr except errors.");
}

CLI::Option* add_meshes_option(CLI::App& app, std::string& text) {
    return app
        .add_option("--meshes", text,
                    "Draw element meshes in PNG pictures: auto = when some element type has a mesh "
                    "file, on = always (types without one as spheres and tubes), off = disks and "
                    "spheres.")
        ->type_name("auto|on|off")
        ->capture_default_str();
}

tessera::RenderOptions::Meshes parse_meshes_option(const std::string& text) {
    return tessera::parse_render_meshes(text, "--meshes");
}

CLI::Option* add_gltf_instancing_option(CLI::App& app, std::string& text) {
    return app
        .add_option("--gltf-instancing", text,
                    "How a .gltf/.glb output places the elements that share a mesh: gpu = one node per "
                    "mesh with the EXT_mesh_gpu_instancing extension (compact; the extension is marked "
                    "required), nodes = one node per element, for viewers and importers without the "
                    "extension (default: gpu).")
        ->type_name("gpu|nodes");
}

tessera::GltfInstancing parse_gltf_instancing_option(const std::string& text) {
    return tessera::parse_gltf_instancing(text, "--gltf-instancing");
}

CLI::Option* add_threads_option(CLI::App& app, int& threads) {
    return add_integer_option(app, "--threads", threads,
                              "Worker threads; 0 = all hardware threads. Results are byte-identical for "
                              "every value.");
}

CLI::Option* add_seed_option(CLI::App& app, std::uint64_t& seed) {
    return add_integer_option(app, "--seed", seed,
                              "Seed of every random draw (unsigned 64-bit). The same seed and options give "
                              "the same output, whatever --threads is.");
}

tessera::LoadOptions input_load_options(const std::string& input_domain_text, const std::string& flag) {
    tessera::LoadOptions options;
    if (!input_domain_text.empty()) options.input_domain = tessera::parse_box_domain(input_domain_text, flag);
    return options;
}

namespace {

// A JSON file's domain replaced by a window that holds none of its elements is a wrong
// window (another axis range, a typo): said here, not later as an empty exemplar or a domain
// too small; one that leaves some out would make an exemplar with elements outside its own
// domain. A CSV's loader says the same of its points.
void require_elements_inside(const tessera::Exemplar& data, const std::string& path, const std::string& window,
                             const std::string& flag) {
    size_t outside = 0;
    const tessera::Element* first = nullptr;
    for (const tessera::Element& e : data.elements)
        if (!data.domain.inside(e.position)) {
            ++outside;
            if (!first) first = &e;
        }
    if (outside == 0) return;  // (no elements: the loader's own error says so)
    std::ostringstream where;
    if (outside == data.elements.size())
        where << "none of the " << data.elements.size() << " elements of " << path << " lies in " << flag << " "
              << window << " (the first is at ";
    else
        where << outside << " of the " << data.elements.size() << " elements of " << path << " lie outside " << flag
              << " " << window << " (the first at ";
    where << first->position.x << "," << first->position.y;
    if (data.dimension == 3) where << "," << first->position.z;
    where << ")";
    throw tessera::Error(tessera::ErrorKind::domain, where.str());
}

}  // namespace

tessera::Exemplar load_input(const std::string& path, const std::string& input_domain_text,
                             const std::string& flag) {
    const tessera::LoadOptions options = input_load_options(input_domain_text, flag);
    tessera::Exemplar data;
    try {
        data = tessera::load(path, options);
    } catch (const tessera::Error& e) {
        // A CSV whose points span no area: say which flag gives the window; a window the
        // data do not fit: say which flag gave it.
        if (e.kind() != tessera::ErrorKind::domain) throw;
        if (options.input_domain)
            throw tessera::Error(e.kind(), std::string(e.what()) + " (" + flag + " " + input_domain_text + ")");
        throw tessera::Error(e.kind(), std::string(e.what()) + " with " + flag);
    }
    if (options.input_domain && extension_of(path) == ".json") {
        // LoadOptions::input_domain applies to CSV only; for JSON the flag replaces the file's domain.
        if (options.input_domain->dimension() != data.dimension)
            throw tessera::Error(tessera::ErrorKind::domain,
                                 flag + " is " + std::to_string(options.input_domain->dimension()) +
                                     "D but " + path + " is " + std::to_string(data.dimension) + "D");
        data.domain = *options.input_domain;
        require_elements_inside(data, path, input_domain_text, flag);
    }
    return data;
}

std::string extension_of(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    const size_t dot = name.rfind('.');
    if (dot == std::string::npos || dot == 0) return "";
    std::string extension = name.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

void check_output_path(const std::string& path, const std::string& flag,
                       std::initializer_list<const char*> allowed) {
    if (path.empty()) fail_option(flag + " needs a file name");
    const std::string extension = extension_of(path);
    std::string list;
    bool found = false;
    for (const char* a : allowed) {
        list += (list.empty() ? "" : ", ") + std::string(a);
        found = found || extension == a;
    }
    if (!found)
        fail_option(flag + " " + path + ": unsupported extension '" + extension + "' (supported: " + list +
                    ")");
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code error;
    if (!parent.empty() && !std::filesystem::is_directory(parent, error))
        throw tessera::Error(tessera::ErrorKind::io,
                             "cannot write " + path + ": directory " + parent.string() + " does not exist");
}

void check_arrangement_output(const std::string& path, const std::string& flag) {
    // ".mesh.ply" ends in ".ply"; it is listed for the message.
    check_output_path(path, flag,
                      {".json", ".csv", ".ply", ".png", ".svg", ".usda", ".gltf", ".glb", ".obj", ".mesh.ply"});
}

std::string describe_scene(const tessera::Scene& scene) {
    size_t triangles = 0;
    double worst = 0.0;
    for (const tessera::SceneInstance& inst : scene.instances) {
        triangles += scene.meshes[inst.mesh].triangles.size();
        worst = std::max(worst, inst.fit_error);
    }
    return std::to_string(scene.instances.size()) + " instances, " + std::to_string(scene.meshes.size()) +
           " meshes, " + std::to_string(triangles) + " triangles, max rigid fit error " + format_number(worst);
}

std::string format_number(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

}  // namespace tessera_cli
