// The text forms of shared options (tessera/option_text.hpp): the output domain spec,
// axis directions, boundary sides and the det method's enumerations.
#include "tessera/option_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera {
namespace {

[[noreturn]] void bad(const std::string& message) { throw Error(ErrorKind::option, message); }

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::optional<double> parse_number(std::string text) {
    const size_t first = text.find_first_not_of(" \t");
    const size_t last = text.find_last_not_of(" \t");
    if (first == std::string::npos) return std::nullopt;
    text = text.substr(first, last - first + 1);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return std::nullopt;
    return value;
}

// "a,b,c" -> numbers; nullopt if any field is not a number.
std::optional<std::vector<double>> number_list(const std::string& text) {
    std::vector<double> values;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        const auto value = parse_number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (!value) return std::nullopt;
        values.push_back(*value);
        if (comma == std::string::npos) return values;
        start = comma + 1;
    }
}

const char* const domain_usage =
    "expected box:W,H[,D] (size from the input domain's lower corner), "
    "box:xmin,ymin,xmax,ymax[,zmin,zmax] (corners), polygon:FILE.json, polygon:x1,y1,x2,y2,..., "
    "mask:FILE.png[@xmin,ymin,xmax,ymax], mesh:FILE[,resolution] or shell:FILE,thickness[,resolution]";

// The spec split into its form; the shaped forms are built once the exemplar is known.
struct DomainSpec {
    std::vector<double> size;            // box:W,H[,D]
    std::optional<Domain> box;           // box:corners
    std::string shape, argument;         // polygon:, mask:, mesh:, shell:
};

DomainSpec split_domain_spec(const std::string& text, const std::string& parameter) {
    for (const char* shape : {"polygon", "mask", "mesh", "shell"}) {
        const std::string prefix = std::string(shape) + ":";
        if (text.rfind(prefix, 0) == 0) {
            DomainSpec spec;
            spec.shape = shape;
            spec.argument = text.substr(prefix.size());
            if (spec.argument.empty()) bad(parameter + ": nothing after '" + prefix + "' in '" + text + "'");
            return spec;
        }
    }
    const std::string prefix = "box:";
    if (text.rfind(prefix, 0) != 0) bad(parameter + ": " + domain_usage + ", got '" + text + "'");
    const std::string numbers = text.substr(prefix.size());
    std::vector<double> values;
    size_t start = 0;
    while (true) {
        const size_t comma = numbers.find(',', start);
        const std::string field = numbers.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto value = parse_number(field);
        if (!value) bad(parameter + ": '" + field + "' is not a number in '" + text + "'; " + domain_usage);
        values.push_back(*value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    DomainSpec spec;
    if (values.size() == 4 || values.size() == 6) {
        spec.box = parse_box_domain(numbers, parameter);
        return spec;
    }
    if (values.size() != 2 && values.size() != 3)
        bad(parameter + ": " + domain_usage + ", got " + std::to_string(values.size()) + " numbers in '" + text + "'");
    for (size_t k = 0; k < values.size(); ++k)
        if (!std::isfinite(values[k]) || !(values[k] > 0.0))
            bad(parameter + ": the size along " + "xyz"[k] + " must be a number > 0, got " + number_text(values[k]) +
                " in '" + text + "'");
    spec.size = values;
    return spec;
}

[[noreturn]] void dimension_mismatch(const std::string& parameter, const std::string& spec, int dimension,
                                     int exemplar_dimension) {
    throw Error(ErrorKind::domain, parameter + " " + spec + " is " + std::to_string(dimension) +
                                       "D but the exemplar is " + std::to_string(exemplar_dimension) + "D");
}

Domain shaped_domain(const DomainSpec& spec, const std::string& text, const Exemplar& exemplar, double scale,
                     const std::string& parameter) {
    const std::string& a = spec.argument;
    const auto need = [&](int dimension) {
        if (exemplar.dimension != dimension) dimension_mismatch(parameter, text, dimension, exemplar.dimension);
    };
    if (spec.shape == "polygon") {
        need(2);
        if (a.size() > 5 && a.substr(a.size() - 5) == ".json") return load_domain_json(a, 2);
        const auto values = number_list(a);
        if (!values || values->size() < 6 || values->size() % 2 != 0)
            bad(parameter + ": expected polygon:FILE.json or polygon:x1,y1,x2,y2,x3,y3,... (at least 3 points), got '" +
                text + "'");
        std::vector<Vec3> outer;
        for (size_t i = 0; i < values->size(); i += 2) outer.push_back({(*values)[i], (*values)[i + 1], 0.0});
        return Domain::polygon(outer);
    }
    if (spec.shape == "mask") {
        need(2);
        const size_t at = a.rfind('@');
        if (at == std::string::npos) {
            const Box b = exemplar.domain.scaled(scale).bounds();
            return Domain::mask(a, b.lo, b.hi);
        }
        const Domain box = parse_box_domain(a.substr(at + 1), parameter + " mask:FILE@");
        if (box.dimension() != 2) bad(parameter + ": a mask box is xmin,ymin,xmax,ymax, got '" + text + "'");
        return Domain::mask(a.substr(0, at), box.bounds().lo, box.bounds().hi);
    }
    // mesh: and shell: take FILE followed by ",numbers"; the file name is everything
    // before the first comma that starts a list of numbers.
    std::string file = a;
    std::vector<double> numbers;
    for (size_t comma = a.find(','); comma != std::string::npos; comma = a.find(',', comma + 1)) {
        if (const auto list = number_list(a.substr(comma + 1))) {
            file = a.substr(0, comma);
            numbers = *list;
            break;
        }
    }
    need(3);
    const auto resolution = [&](size_t index) {
        if (numbers.size() <= index) return 128;
        const double r = numbers[index];
        if (r != std::floor(r) || r < 16 || r > 1024)
            bad(parameter + ": the resolution must be an integer from 16 to 1024, got '" + text + "'");
        return static_cast<int>(r);
    };
    if (spec.shape == "mesh") {
        if (numbers.size() > 1) bad(parameter + ": expected mesh:FILE[,resolution], got '" + text + "'");
        return Domain::mesh(file, resolution(0));
    }
    if (numbers.empty() || numbers.size() > 2 || !(numbers[0] > 0.0))
        bad(parameter + ": expected shell:FILE,thickness[,resolution] with thickness > 0, got '" + text + "'");
    return Domain::shell(file, numbers[0], resolution(1));
}

}  // namespace

void check_domain_spec(const std::string& spec, const std::string& parameter) { split_domain_spec(spec, parameter); }

Domain parse_output_domain(const std::string& text, const Exemplar& exemplar, double scale, const std::string& parameter) {
    if (!std::isfinite(scale) || !(scale > 0.0)) bad("scale must be a number > 0, got " + number_text(scale));
    const DomainSpec spec = split_domain_spec(text, parameter);
    if (!spec.shape.empty()) return shaped_domain(spec, text, exemplar, scale, parameter);
    if (spec.box) {
        if (spec.box->dimension() != exemplar.dimension)
            dimension_mismatch(parameter, text, spec.box->dimension(), exemplar.dimension);
        return *spec.box;
    }
    const int dimension = static_cast<int>(spec.size.size());
    if (dimension != exemplar.dimension) dimension_mismatch(parameter, text, dimension, exemplar.dimension);
    const Vec3 lo = exemplar.domain.bounds().lo;
    const Vec3 size{spec.size[0], spec.size[1], dimension == 3 ? spec.size[2] : 0.0};
    return Domain::box(lo, lo + size, dimension);
}

Vec3 parse_axis_direction(const std::string& text, const std::string& parameter) {
    const bool signed_axis = !text.empty() && (text[0] == '-' || text[0] == '+');
    const std::string axis = signed_axis ? text.substr(1) : text;
    if (axis != "x" && axis != "y" && axis != "z")
        bad(parameter + ": expected an axis with its sign (-x, +x, -y, +y, -z, +z), got '" + text + "'");
    Vec3 v;
    v[axis[0] - 'x'] = text[0] == '-' ? -1.0 : 1.0;
    return v;
}

std::vector<DetOptions::BoundarySide> parse_boundary_sides(const std::string& text, const std::string& parameter) {
    std::vector<DetOptions::BoundarySide> sides;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string side = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (side.size() != 2 || (side[0] != '-' && side[0] != '+') || side[1] < 'x' || side[1] > 'z')
            bad(parameter + ": expected sides such as -x,+x,+y (an axis with its sign), got '" + side + "'");
        sides.push_back({side[1] - 'x', side[0] == '-' ? -1 : 1});
        if (comma == std::string::npos) return sides;
        start = comma + 1;
    }
}

SearchMode parse_search_mode(const std::string& text, const std::string& parameter) {
    if (text == "kcoherence") return SearchMode::kcoherence;
    if (text == "exhaustive") return SearchMode::exhaustive;
    bad(parameter + " must be kcoherence or exhaustive, got '" + text + "'");
}

Matching parse_matching(const std::string& text, const std::string& parameter) {
    if (text == "greedy") return Matching::greedy;
    if (text == "hungarian") return Matching::hungarian;
    bad(parameter + " must be greedy or hungarian, got '" + text + "'");
}

RenderOptions::Meshes parse_render_meshes(const std::string& text, const std::string& parameter) {
    if (text == "auto") return RenderOptions::Meshes::automatic;
    if (text == "on") return RenderOptions::Meshes::on;
    if (text == "off") return RenderOptions::Meshes::off;
    bad(parameter + " must be auto, on or off, got '" + text + "'");
}

GltfInstancing parse_gltf_instancing(const std::string& text, const std::string& parameter) {
    if (text == "gpu") return GltfInstancing::gpu;
    if (text == "nodes") return GltfInstancing::nodes;
    bad(parameter + " must be gpu or nodes, got '" + text + "'");
}

const char* to_string(SearchMode mode) { return mode == SearchMode::kcoherence ? "kcoherence" : "exhaustive"; }
const char* to_string(Matching matching) { return matching == Matching::greedy ? "greedy" : "hungarian"; }

}  // namespace tessera
