// apps/tessera/common.hpp — the vocabulary every `tessera` subcommand shares:
// the options that mean the same everywhere (-o, --seed, --quiet, --threads,
// --input-domain), loading an input with --input-domain, up-front checks of
// output paths, and the mapping from tessera::ErrorKind to exit codes.
// The CLI only parses, calls the library and prints; nothing here computes.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "tessera/tessera.hpp"

namespace tessera_cli {

// Exit codes (docs/cli.md, "Exit codes").
inline constexpr int exit_ok = 0;
inline constexpr int exit_option = 2;       // bad option / usage (also every CLI11 parse error)
inline constexpr int exit_input = 3;        // invalid input data
inline constexpr int exit_domain = 4;       // a domain with no area/volume, or too small
inline constexpr int exit_io = 5;           // a file could not be read or written
inline constexpr int exit_internal = 70;    // a bug in tessera (EX_SOFTWARE)
inline constexpr int exit_cancelled = 130;  // interrupted (128 + SIGINT)

int exit_code(tessera::ErrorKind kind);

// Prints the one-line error message `tessera: error: <message>` to stderr.
void print_error(const std::string& message);

// Throws tessera::Error(option) with `message` (which names the flag at fault).
[[noreturn]] void fail_option(const std::string& message);

// The integer that `text` writes in decimal notation, with an optional sign, fraction and
// exponent ("1e3", "1000.0", "-2.5e1", "+7"), as plain digits with an optional '-'
// ("1000", "-25"); nullopt when `text` is not such a number or its value is not an
// integer ("1.5", "1e-3", "abc", "0x10"). Exact: no rounding through floating point.
std::optional<std::string> integer_digits(const std::string& text);

// The CLI11 transform every integer option goes through (add_integer_option): turns any
// decimal notation of an integral value in [lo, hi] into plain digits, and fails naming
// the value when it is not a number, not integral, or out of range (CLI11 then names the
// option).
CLI::Validator integer_notation(long long lo, unsigned long long hi);

// Adds an integer option: the one way the subcommands declare one, so that every integer
// option takes the same notations (integer_notation) and shows its default.
template <class T>
CLI::Option* add_integer_option(CLI::App& app, const std::string& name, T& value, const std::string& help) {
    static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>);
    return app.add_option(name, value, help)
        ->transform(integer_notation(static_cast<long long>(std::numeric_limits<T>::min()),
                                     static_cast<unsigned long long>(std::numeric_limits<T>::max())))
        ->capture_default_str();
}

// Shared options. Each adds the option to `app` with the same name, meaning and
// help text in every subcommand.
CLI::Option* add_output_option(CLI::App& app, std::string& path, const std::string& what, bool required);
// `operand` names the positional the window belongs to (INPUT, EXEMPLAR, FILE).
CLI::Option* add_input_domain_option(CLI::App& app, std::string& text, const std::string& operand);
CLI::Option* add_quiet_option(CLI::App& app, bool& quiet);
CLI::Option* add_threads_option(CLI::App& app, int& threads);
CLI::Option* add_seed_option(CLI::App& app, std::uint64_t& seed);
// --meshes auto|on|off: draw element meshes in PNG pictures (RenderOptions::meshes).
CLI::Option* add_meshes_option(CLI::App& app, std::string& text);
// The value of --meshes; fails with an option error naming the flag for another value.
tessera::RenderOptions::Meshes parse_meshes_option(const std::string& text);
// --gltf-instancing gpu|nodes: how .gltf/.glb outputs place instances (SaveOptions::gltf_instancing).
CLI::Option* add_gltf_instancing_option(CLI::App& app, std::string& text);
// The value of --gltf-instancing; fails with an option error naming the flag for another value.
tessera::GltfInstancing parse_gltf_instancing_option(const std::string& text);

// The library names the option field at fault at the start of its option errors
// ("width: ...", tessera/render.hpp); `names` pairs such fields with this command's flags.
using FlagNames = std::initializer_list<std::pair<const char*, const char*>>;

// Rethrows the exception being handled, an option error starting with a field of `names`
// ("width: ...") as the same error naming the flag ("--width: ...").
[[noreturn]] void rethrow_with_flag_names(const tessera::Error& e, FlagNames names);

// Runs `work`, naming flags instead of fields in its option errors (rethrow_with_flag_names).
template <class Work>
auto with_flag_names(FlagNames names, Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const tessera::Error& e) {
        rethrow_with_flag_names(e, names);
    }
}

// --meshes on asks for element meshes, which only .png pictures show: an option error for
// another picture `path`, before any work is done.
void check_meshes_for_picture(tessera::RenderOptions::Meshes meshes, const std::string& path);

// Loads an exemplar or arrangement from .json or .csv. A non-empty
// `input_domain_text` ("xmin,ymin,xmax,ymax[,zmin,zmax]", the value of the option
// named `flag`) is the observation window: CSV files are read with it, and for a
// JSON file it replaces the file's own domain (its dimension must match).
tessera::Exemplar load_input(const std::string& path, const std::string& input_domain_text,
                             const std::string& flag = "--input-domain");

// The load options of an input with the observation window `input_domain_text` (empty =
// none), an option error naming `flag` when it is not a box; for tessera::load_animation.
tessera::LoadOptions input_load_options(const std::string& input_domain_text,
                                        const std::string& flag = "--input-domain");

// Lower-cased extension including the dot ("" if none), as the library reads it.
std::string extension_of(const std::string& path);

// Checks before any work is done that `path` (the value of `flag`) has one of the
// `allowed` extensions (e.g. {".png", ".svg"}) and that its directory exists, so that
// a run that would fail at the end fails at the start instead.
void check_output_path(const std::string& path, const std::string& flag,
                       std::initializer_list<const char*> allowed);

// The -o of synth and edit: data (.json, .csv, .ply), pictures (.png, .svg) or
// scenes of the elements' geometry (.usda, .gltf, .glb, .obj, .mesh.ply); checked up
// front like check_output_path.
void check_arrangement_output(const std::string& path, const std::string& flag);

// One line about a scene: instances, meshes, triangles and the largest rigid fit error.
std::string describe_scene(const tessera::Scene& scene);

// Writes `data` (an Exemplar or an Arrangement) by the extension of `path` through the
// library (tessera::save; a scene path through tessera::save_scene, whose scene it
// describes): returns describe_scene for a scene path, else "".
template <class Data>
std::string write_arrangement(const Data& data, const std::string& path,
                              const tessera::SaveOptions& options) {
    if (!tessera::is_scene_path(path)) {
        tessera::save(data, path, options);
        return "";
    }
    return describe_scene(tessera::save_scene(data, path, options));
}

// Formats a double compactly for messages ("%g").
std::string format_number(double value);

// Subcommands: each registers itself on `app` and returns the function that runs it
// after parsing (which throws tessera::Error on failure).
struct Subcommand {
    CLI::App* app = nullptr;
    std::function<void()> run;
};
Subcommand add_synth_command(CLI::App& app);
Subcommand add_metrics_command(CLI::App& app);
Subcommand add_render_command(CLI::App& app);
Subcommand add_edit_command(CLI::App& app);
Subcommand add_scene_command(CLI::App& app);
Subcommand add_analyze_command(CLI::App& app);
Subcommand add_recombine_command(CLI::App& app);
Subcommand add_animate_command(CLI::App& app);
Subcommand add_grow_command(CLI::App& app);
Subcommand add_brush_command(CLI::App& app);
Subcommand add_world_command(CLI::App& app);
Subcommand add_studio_command(CLI::App& app);

}  // namespace tessera_cli
