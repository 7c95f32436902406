// apps/tessera/cmd_brush.cpp — `tessera brush SESSION.json -o OUTPUT`: replays a brush
// session file (palette, paint / direction / erase strokes, fill; docs/brush.md) headless,
// with the result the studio shows for the same session.
#include <cstdio>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "interrupt_scope.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"

namespace tessera_cli {
namespace {

struct BrushArgs {
    std::string session, output, preview;
    std::string gltf_instancing = "gpu";
    bool quiet = false;
    tessera::BrushOptions options;  // only for the flags' checks; the session's options are overridden
    OptionFlags flags;              // BrushOptions as flags, from the table (tessera/option_table.hpp)
};

// A surface canvas's mesh as an opaque light-grey class "surface" for the 3D preview, which
// draws spheres with a z-buffer: spheres at the vertices and triangle centres, sunk below the
// surface by their radius, hide the elements on the far side (the back of a closed surface
// seen through the front made the picture unreadable).
void add_surface(const tessera::BrushCanvas& canvas, tessera::Arrangement& shot) {
    const tessera::DomainSource src = canvas.domain().source();
    if (canvas.domain().kind() != tessera::Domain::Kind::shell || src.file.empty()) return;
    tessera::TriangleMesh mesh = tessera::read_triangle_mesh(src.file);
    for (tessera::Vec3& v : mesh.vertices) v = src.origin + (v - src.origin) * src.scale;
    std::vector<tessera::Vec3> normals(mesh.vertices.size());
    double edges = 0.0;
    for (const auto& t : mesh.triangles) {
        const tessera::Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        for (int k = 0; k < 3; ++k) normals[t[k]] += tessera::cross(b - a, c - a);
        edges += tessera::norm(b - a) + tessera::norm(c - b) + tessera::norm(a - c);
    }
    const double radius = 0.6 * edges / (3.0 * std::max<size_t>(1, mesh.triangles.size()));
    tessera::ElementType surface;
    surface.name = "surface";
    surface.color = "#d9d9d9";
    const int type = static_cast<int>(shot.types.size());
    shot.types.push_back(surface);
    auto sunk = [&](const tessera::Vec3& p, const tessera::Vec3& n) {
        const double len = tessera::norm(n);
        shot.add_element(type, {len > 0.0 ? p - n * (1.3 * radius / len) : p}, radius);
    };
    for (size_t i = 0; i < mesh.vertices.size(); ++i) sunk(mesh.vertices[i], normals[i]);
    for (const auto& t : mesh.triangles)
        sunk((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0,
             normals[t[0]] + normals[t[1]] + normals[t[2]]);
}

// The picture: the elements, with the direction strokes drawn as a faint dotted class
// "stroke" (2D only), and a surface canvas's surface (add_surface); a copy, the output is
// unchanged.
tessera::Arrangement with_strokes(const tessera::BrushCanvas& canvas) {
    tessera::Arrangement shot = canvas.arrangement();
    add_surface(canvas, shot);
    if (shot.dimension != 2 || canvas.direction_strokes().empty()) return shot;
    tessera::ElementType stroke;
    stroke.name = "stroke";
    stroke.color = "#c8c8c8";
    const int type = static_cast<int>(shot.types.size());
    shot.types.push_back(stroke);
    const tessera::Box b = shot.domain.bounds();
    const double step = 0.004 * std::max(b.size().x, b.size().y);
    for (const tessera::Stroke& s : canvas.direction_strokes())
        for (size_t i = 0; i + 1 < s.points.size(); ++i) {
            const tessera::Vec3 a = s.points[i], d = s.points[i + 1] - a;
            const int n = std::max(1, static_cast<int>(tessera::norm(d) / (3 * step)));
            for (int k = 0; k < n; ++k) shot.add_element(type, {a + d * (static_cast<double>(k) / n)}, step);
        }
    return shot;
}

void run_brush(BrushArgs& args) {
    StatusPrinter status("brush", args.quiet, std::cerr);
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    check_arrangement_output(args.output, "-o");
    if (!args.preview.empty()) check_output_path(args.preview, "--preview", {".png", ".svg"});
    args.flags.apply(tessera::brush_option_table(), args.options);  // bad flags fail before any file is read
    tessera::SaveOptions save_options;
    save_options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);
    tessera::BrushSession session =
        status.step("reading " + args.session, [&] { return tessera::read_brush_session(args.session); });
    args.flags.apply(tessera::brush_option_table(), session.options);
    tessera::Progress progress = status.progress([] { return !interrupt_requested(); }, "iteration");
    std::optional<tessera::BrushCanvas> canvas;
    try {
        canvas.emplace(tessera::replay_brush_session(session, progress));
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();
    const tessera::Arrangement& result = canvas->arrangement();
    if (!args.preview.empty())
        status.step("writing " + args.preview, [&] { tessera::render_to_file(with_strokes(*canvas), args.preview); });
    status.step("writing " + args.output, [&] { return write_arrangement(result, args.output, save_options); });
    if (!args.quiet) {
        const tessera::BrushCanvas::Energies e = canvas->energies();
        char line[320];
        std::snprintf(line, sizeof line,
                      "done: %zu elements from %zu operations; energy per sample: distribution %.4g, conflict %.4g, "
                      "graph %.4g, alignment %.4g, continuity %.4g, rigidity %.4g",
                      result.elements.size(), session.ops.size(), e.distribution, e.conflict, e.graph, e.alignment,
                      e.continuity, e.rigidity);
        std::cerr << line << "; wrote " << args.output << (args.preview.empty() ? "" : " and " + args.preview)
                  << std::endl;
    }
}

}  // namespace

Subcommand add_brush_command(CLI::App& app) {
    auto args = std::make_shared<BrushArgs>();
    CLI::App* cmd = app.add_subcommand(
        "brush",
        "Replay a brush session file (docs/brush.md): palette entries painted along strokes, direction strokes, "
        "erase strokes and 'fill the rest', as the studio does, and write the result.");
    cmd->add_option("SESSION", args->session, "The session file (.json, \"format\": \"tessera-brush\").")
        ->required()
        ->type_name("FILE");
    add_output_option(*cmd, args->output,
                      "The arrangement: .json, .csv, .ply, .png, .svg, or a scene .usda, .gltf, .glb, .obj or "
                      ".mesh.ply.",
                      true);
    cmd->add_option("--preview", args->preview, "Also write a picture of the result with its strokes (.png or .svg).")
        ->type_name("FILE");
    args->flags.add(*cmd, {method_options("brush", tessera::brush_option_table())});
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_brush(*args); }};
}

}  // namespace tessera_cli
