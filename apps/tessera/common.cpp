// apps/tessera/common.cpp — the shared CLI vocabulary: common options, input
// loading with --input-domain, output path checks and exit codes.
#include "common.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

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
    return app
        .add_option("--threads", threads,
                    "Worker threads; 0 = all hardware threads. Results are byte-identical for "
                    "every value.")
        ->capture_default_str();
}

CLI::Option* add_seed_option(CLI::App& app, std::uint64_t& seed) {
    return app
        .add_option("--seed", seed,
                    "Seed of every random draw (unsigned 64-bit). The same seed and options give "
                    "the same output, whatever --threads is.")
        ->capture_default_str();
}

tessera::Exemplar load_input(const std::string& path, const std::string& input_domain_text,
                             const std::string& flag) {
    tessera::LoadOptions options;
    if (!input_domain_text.empty()) options.input_domain = tessera::parse_box_domain(input_domain_text, flag);
    tessera::Exemplar data;
    try {
        data = tessera::load(path, options);
    } catch (const tessera::Error& e) {
        // A CSV whose points span no area: say which flag gives the window.
        if (e.kind() != tessera::ErrorKind::domain || options.input_domain) throw;
        throw tessera::Error(e.kind(), std::string(e.what()) + " with " + flag);
    }
    if (options.input_domain && extension_of(path) == ".json") {
        // LoadOptions::input_domain applies to CSV only; for JSON the flag replaces the file's domain.
        if (options.input_domain->dimension() != data.dimension)
            throw tessera::Error(tessera::ErrorKind::domain,
                                 flag + " is " + std::to_string(options.input_domain->dimension()) +
                                     "D but " + path + " is " + std::to_string(data.dimension) + "D");
        data.domain = *options.input_domain;
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
